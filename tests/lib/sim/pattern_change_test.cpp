// predict_pattern_change: the first-order response of an equilibrium to new patterns is a
// Newton step with the old Hessian, so it leaves an error of second order in the change.
#include "sim/pattern_change.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "sim/cloth_energy.h"
#include "sim/drape_solver.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

double mean_distance(const MatrixX3d& a, const MatrixX3d& b) { return (a - b).rowwise().norm().mean(); }

struct Hanging {
  Garment g;
  std::vector<int> pinned;
  MatrixX3d equilibrium;  // of g's own patterns
};

// A 0.3 m cotton sheet hanging from its top edge, at equilibrium (relative residual 1e-10).
Hanging hanging_sheet() {
  Hanging h{test::square_panel(10, 0.3), {}, {}};
  h.pinned = test::top_row(h.g);
  DrapeSettings tight;
  tight.tolerance = 1e-10;
  const DrapeResult r = solve_drape(test::cotton_model(h.g, h.pinned), h.g.V, tight);
  EXPECT_TRUE(r.stats.converged) << r.stats.message;
  h.equilibrium = r.V;
  return h;
}

// The patterns lengthened along the warp (pattern y) by `change`; the pins stay where they are.
ClothModel lengthened(const Hanging& h, double change) {
  Garment longer = h.g;
  longer.P.col(1) *= 1.0 + change;
  longer.V = h.equilibrium;
  return test::cotton_model(longer, h.pinned);
}

// Lengthening the patterns by 0.4 % and by 0.2 %: the predicted drape's distance to the new
// equilibrium, relative to the start's, is of first order in the change (the step's own error
// is of second order): small, and about halving with the change.
TEST(PatternChange, LeavesAnErrorOfSecondOrderInTheChange) {
  const Hanging h = hanging_sheet();
  Garment own = h.g;
  own.V = h.equilibrium;
  const ClothModel before = test::cotton_model(own, h.pinned);
  DrapeSettings tight;
  tight.tolerance = 1e-10;
  std::vector<double> relative;
  for (const double change : {0.004, 0.002}) {
    const ClothModel after = lengthened(h, change);
    const PatternChangeStep step = predict_pattern_change(before, after, h.equilibrium);
    ASSERT_TRUE(step.applied) << step.message;
    EXPECT_TRUE(step.near_equilibrium);
    EXPECT_EQ(step.step_fraction, 1.0);
    EXPECT_LT(step.start_residual, 1e-8);
    const DrapeResult end = solve_drape(after, h.equilibrium, tight);
    ASSERT_TRUE(end.stats.converged);
    const double moved = mean_distance(h.equilibrium, end.V);
    EXPECT_GT(moved, 1e-4 * change / 0.004);  // the change moves the sheet (0.6 mm at 0.4 %)
    relative.push_back(mean_distance(step.V, end.V) / moved);
  }
  EXPECT_LT(relative[0], 0.05);
  EXPECT_LT(relative[1], 0.7 * relative[0]);
}

// A start that is not an equilibrium of its patterns (the flat sheet, before it hangs: its
// weight is unbalanced under the old patterns as under the new) is returned as it is, with the
// reason; so is an equilibrium whose patterns did not change.
TEST(PatternChange, LeavesAStartThatIsNoEquilibriumAlone) {
  const Hanging h = hanging_sheet();
  const ClothModel before = test::cotton_model(h.g, h.pinned);
  const ClothModel after = lengthened(h, 1e-4);
  const PatternChangeStep flat = predict_pattern_change(before, after, h.g.V);
  EXPECT_FALSE(flat.applied);
  EXPECT_FALSE(flat.near_equilibrium);
  EXPECT_NE(flat.message.find("not an equilibrium"), std::string::npos) << flat.message;
  EXPECT_NEAR(flat.start_residual, 1.0, 0.05);  // the whole weight
  EXPECT_EQ(flat.V, h.g.V);

  const PatternChangeStep same = predict_pattern_change(before, before, h.equilibrium);
  EXPECT_FALSE(same.applied);
  EXPECT_EQ(same.V, h.equilibrium);
}

// An extreme change (the patterns twice as wide, gathered under pins that stay where they were):
// the step is finite and lowers the new energy, or the start is left as it is; either way the
// re-drape from it converges.
TEST(PatternChange, AnExtremeGatheringGivesAFiniteStartThatDrapes) {
  const Hanging h = hanging_sheet();
  Garment own = h.g;
  own.V = h.equilibrium;
  const ClothModel before = test::cotton_model(own, h.pinned);
  Garment wide = own;
  wide.P.col(0) *= 2.0;
  const ClothModel after = test::cotton_model(wide, h.pinned);
  const PatternChangeStep step = predict_pattern_change(before, after, h.equilibrium);
  ASSERT_TRUE(step.V.allFinite());
  const ClothEnergy energy(after);
  const double e0 = energy.evaluate(h.equilibrium, nullptr, nullptr, HessianKind::Exact).total();
  const double e1 = energy.evaluate(step.V, nullptr, nullptr, HessianKind::Exact).total();
  if (step.applied) EXPECT_LT(e1, e0);
  else EXPECT_EQ(step.V, h.equilibrium) << step.message;
  const DrapeResult end = solve_drape(after, step.V, DrapeSettings{});
  EXPECT_TRUE(end.stats.converged) << end.stats.message;
}

// drape-free's re-drape: the predictor factorises where the solve then factorises, so the
// solve reuses the predictor's analysis. It ends where a solve with its own factorisation ends,
// and reports only its own factorisations. The solve's precision is its settings' whatever the
// predictor left (here double, single for the solve).
TEST(PatternChange, HandsItsAnalysisToTheReDrape) {
  const Hanging h = hanging_sheet();
  Garment own = h.g;
  own.V = h.equilibrium;
  const ClothModel before = test::cotton_model(own, h.pinned);
  const ClothModel after = lengthened(h, 0.004);
  BisectedCholesky shared;  // as the solve's own (the sheet is small enough to be factorised whole)
  PatternChangeSettings change;
  change.factor_precision = FactorPrecision::Double;
  const PatternChangeStep step = predict_pattern_change(before, after, h.equilibrium, change, &shared);
  ASSERT_TRUE(step.applied) << step.message;
  EXPECT_EQ(shared.factorizations(), 1);
  EXPECT_EQ(shared.precision(), FactorPrecision::Double);
  const double analysis = shared.analyze_seconds();
  EXPECT_GT(analysis, 0.0);

  DrapeSettings settings;
  settings.tolerance = 1e-10;
  const DrapeResult alone = solve_drape(after, step.V, settings);
  const DrapeResult reused = solve_drape(after, step.V, settings, {}, &shared);
  ASSERT_TRUE(alone.stats.converged && reused.stats.converged);
  EXPECT_EQ(shared.analyze_seconds(), analysis);  // not analysed again
  EXPECT_EQ(shared.precision(), reused.stats.double_precision_fallback ? FactorPrecision::Double : settings.factor_precision);
  EXPECT_EQ(reused.stats.factorizations, alone.stats.factorizations);
  EXPECT_EQ(shared.factorizations(), 1 + reused.stats.factorizations);
  EXPECT_EQ(reused.stats.newton_iterations, alone.stats.newton_iterations);
  EXPECT_LT((reused.V - alone.V).cwiseAbs().maxCoeff(), 1e-12);
}

// A factorisation analysed for another pattern is analysed again before the solve uses it.
TEST(PatternChange, ReDrapeReanalysesAFactorisationOfAnotherPattern) {
  const Hanging h = hanging_sheet();
  const ClothModel after = lengthened(h, 0.004);
  BisectedCholesky other;
  other.analyze(ClothEnergy(test::cotton_model(test::square_panel(6, 0.3), {})).pattern());
  const DrapeResult alone = solve_drape(after, h.equilibrium, DrapeSettings{});
  const DrapeResult reused = solve_drape(after, h.equilibrium, DrapeSettings{}, {}, &other);
  ASSERT_TRUE(alone.stats.converged && reused.stats.converged) << reused.stats.message;
  EXPECT_EQ(reused.stats.newton_iterations, alone.stats.newton_iterations);
  EXPECT_LT((reused.V - alone.V).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(PatternChange, RefusesModelsOfTwoGarments) {
  const Hanging h = hanging_sheet();
  const ClothModel before = test::cotton_model(h.g, h.pinned);
  const ClothModel unpinned = test::cotton_model(h.g, {});
  EXPECT_THROW(predict_pattern_change(before, unpinned, h.equilibrium), ArgumentError);
}

} // namespace
} // namespace foldsketch
