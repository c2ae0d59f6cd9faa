#include "sim/pattern_change.h"

#include <chrono>
#include <cmath>

#include "core/error.h"
#include "sim/bisected_cholesky.h"
#include "sim/cloth_energy.h"
#include "sim/drape_solver.h"

namespace foldsketch {
namespace {
bool same_garment(const ClothModel& a, const ClothModel& b) {
  if (a.vertex_count != b.vertex_count || a.triangles != b.triangles || a.pins.size() != b.pins.size() ||
      static_cast<bool>(a.self_contact) != static_cast<bool>(b.self_contact))
    return false;
  for (size_t k = 0; k < a.pins.size(); ++k)
    if (a.pins[k].vertex != b.pins[k].vertex || a.pins[k].position != b.pins[k].position) return false;
  return true;
}
} // namespace

PatternChangeStep predict_pattern_change(const ClothModel& before, const ClothModel& after, const MatrixX3d& x0,
                                         const PatternChangeSettings& settings, BisectedCholesky* factorisation) {
  const auto start = std::chrono::steady_clock::now();
  if (!same_garment(before, after)) throw ArgumentError("predict_pattern_change: the two models are not the same garment");
  if (x0.rows() != after.vertex_count || !x0.allFinite())
    throw ArgumentError("predict_pattern_change: the start has the wrong size or non-finite coordinates");
  PatternChangeStep step;
  step.V = x0;
  for (const Pin& p : after.pins) step.V.row(p.vertex) = p.position.transpose();
  const auto done = [&](const char* why) {
    step.message = why;
    step.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return step;
  };
  ClothEnergy old_energy(before);
  const ClothEnergy new_energy(after);
  const int n = new_energy.free_count();
  if (n == 0) return done("no free vertices");

  // The start's residual under its own patterns, scaled as the solver scales it (the Hessian's
  // pattern grown for the self-contact pairs at the start first).
  VectorXd g_old, g;
  old_energy.prepare(step.V);
  SparseMatrix H = old_energy.pattern();
  old_energy.evaluate(step.V, &g_old, &H, HessianKind::Exact);
  const double scale = residual_scale(before, old_energy);
  step.start_residual = g_old.norm() / scale;
  const double e0 = new_energy.evaluate(step.V, &g, nullptr, HessianKind::Exact).total();
  step.change_residual = g.norm() / scale;
  if (!(g_old.norm() <= settings.max_force_ratio * g.norm()))
    return done("the start is not an equilibrium of its patterns (or the patterns did not change)");
  step.near_equilibrium = true;

  BisectedCholesky own_factorisation;
  BisectedCholesky& cholesky = factorisation ? *factorisation : own_factorisation;
  if (!cholesky.analysed_for(H)) cholesky.analyze(H);
  cholesky.set_precision(settings.factor_precision);
  bool definite = cholesky.factorize(H);
  VectorXd dx;
  if (definite) dx = cholesky.solve(-g);
  if (settings.factor_precision == FactorPrecision::Single && (!definite || !cholesky.last_solve_trusted())) {
    // Too ill-conditioned for single precision (refused, or a solve not to be trusted): the
    // same in double.
    cholesky.set_precision(FactorPrecision::Double);
    definite = cholesky.factorize(H);
    if (definite) dx = cholesky.solve(-g);
  }
  if (!definite) return done("the start is not a stable equilibrium of its patterns (indefinite Hessian)");
  double largest = 0.0;
  for (int a = 0; a < n; ++a) largest = std::max(largest, dx.segment<3>(3 * a).norm());
  if (!std::isfinite(largest)) return done("the predicted step is not finite");
  if (after.body && largest > settings.max_displacement) {
    dx *= settings.max_displacement / largest;
    largest = settings.max_displacement;
  }
  const double slope = g.dot(dx);
  if (!(slope < 0.0)) return done("the predicted step does not lower the energy");
  // With self-contact, no further than the solver's straight steps go: no layer passes another.
  const double longest = longest_layer_safe_step(after, step.V, dx, new_energy.free_vertices());
  for (double alpha = longest; alpha >= kLineSearchMinStep; alpha *= 0.5) {
    MatrixX3d trial = moved_along(step.V, dx, {}, new_energy.free_vertices(), alpha);
    const double e = new_energy.evaluate(trial, nullptr, nullptr, HessianKind::Exact).total();
    if (std::isfinite(e) && e <= e0 + kLineSearchArmijo * alpha * slope) {
      step.V = std::move(trial);
      step.applied = true;
      step.step_fraction = alpha;
      step.step_length = alpha * largest;
      return done("");
    }
  }
  return done("no decrease of the energy along the predicted step");
}

} // namespace foldsketch
