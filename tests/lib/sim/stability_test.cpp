// Stability of an equilibrium: the exact Hessian positive definite up to kNeutralCurvature
// times the mass, and the direction of most negative curvature where it is not.
#include <gtest/gtest.h>

#include "samples/grid_garment.h"
#include "sim/drape_solver.h"
#include "sim/stability.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// A sheet at rest in zero gravity, unpinned: its Hessian is singular (the six rigid motions
// cost nothing), and that is neutral, not unstable.
TEST(Stability, RigidMotionsAreNeutral) {
  const Garment g = grid_garment({flat_panel("sheet", 12, 8, 0.6, 0.4, {0, 1, 0}, Vector3d::UnitX(), Vector3d::UnitY())}, 1e-9);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  scene.gravity = Vector3d::Zero();
  const ClothModel model = cloth_model(g, scene, nullptr, {});
  ClothEnergy energy(model);  // keeps a reference to the model
  const StabilityCheck check = check_stability(energy, g.V);
  EXPECT_TRUE(check.stable);
  EXPECT_EQ(check.factorizations, 1);
  EXPECT_EQ(check.mode.size(), 0);
}

// A hanging sheet's equilibrium is a minimum.
TEST(Stability, HangingSheetIsStable) {
  const Garment hanging = test::square_panel(10, 0.3);  // in the z = 0 plane, y up
  const ClothModel model = test::cotton_model(hanging, test::top_row(hanging));
  const DrapeResult r = solve_drape(model, hanging.V, {});
  ASSERT_TRUE(r.stats.converged) << r.stats.message;
  EXPECT_EQ(r.stats.stability, Stability::Stable);
  ClothEnergy energy(model);
  EXPECT_TRUE(check_stability(energy, r.V).stable);
}

// A flat sheet held at 0.97 of its width between its left and right edges, no gravity: the
// compression makes wrinkles out of the plane cost negative energy. The mode found points out
// of the plane, its curvature is negative, and the energy falls along it either way.
TEST(Stability, SqueezedFlatSheetHasNegativeCurvatureOutOfItsPlane) {
  GridPanel p = flat_panel("sheet", 16, 8, 0.4, 0.2, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY());
  for (int v = 0; v < p.drape.rows(); ++v) p.drape(v, 0) *= 0.97;
  const Garment g = grid_garment({p}, 1e-12);
  std::vector<int> held;
  for (int v = 0; v < g.V.rows(); ++v)
    if (g.V(v, 0) < 1e-9 || g.V(v, 0) > 0.97 * 0.4 - 1e-9) held.push_back(v);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  scene.gravity = Vector3d::Zero();
  const ClothModel model = cloth_model(g, scene, nullptr, held);
  ClothEnergy energy(model);
  const StabilityCheck check = check_stability(energy, g.V);
  ASSERT_FALSE(check.stable);
  EXPECT_LT(check.lowest_eigenvalue, -kNeutralCurvature);
  ASSERT_EQ(check.mode.size(), 3 * energy.free_count());
  double in_plane = 0, out_of_plane = 0;
  for (int a = 0; a < energy.free_count(); ++a) {
    in_plane += check.mode.segment<2>(3 * a).squaredNorm();
    out_of_plane += check.mode(3 * a + 2) * check.mode(3 * a + 2);
  }
  EXPECT_GT(out_of_plane, 100 * in_plane);
  // Along the mode, E(x + t m) - E(x) = lambda t^2 / 2 (m of unit M-norm) for small t.
  const double e0 = energy.evaluate(g.V, nullptr, nullptr, HessianKind::Exact).total();
  for (double sign : {1.0, -1.0}) {
    MatrixX3d moved = g.V;
    const double t = 1e-5;  // sqrt(kg) m
    for (int a = 0; a < energy.free_count(); ++a)
      moved.row(energy.free_vertices()[a]) += sign * t * check.mode.segment<3>(3 * a).transpose();
    const double change = energy.evaluate(moved, nullptr, nullptr, HessianKind::Exact).total() - e0;
    EXPECT_NEAR(change, 0.5 * check.lowest_eigenvalue * t * t, 0.05 * std::abs(0.5 * check.lowest_eigenvalue * t * t));
  }
}

} // namespace
} // namespace foldsketch
