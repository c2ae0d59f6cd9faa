// StepCurvature: the second-order part of a step that turns cloth as a whole is the rotation's
// own, so the curved path keeps edge lengths where the straight one stretches them.
#include "sim/step_curvature.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim/cloth_energy.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// Free-vertex step of every vertex of x moved by `motion(position)`.
template <class Motion>
VectorXd step_of(const ClothEnergy& energy, const MatrixX3d& x, Motion motion) {
  VectorXd dx(3 * energy.free_count());
  for (int a = 0; a < energy.free_count(); ++a) dx.segment<3>(3 * a) = motion(Vector3d(x.row(energy.free_vertices()[a]).transpose()));
  return dx;
}

MatrixX3d moved_by(const ClothEnergy& energy, const MatrixX3d& x, const VectorXd& dx, const VectorXd& c) {
  MatrixX3d y = x;
  for (int a = 0; a < energy.free_count(); ++a) {
    y.row(energy.free_vertices()[a]) += dx.segment<3>(3 * a).transpose();
    if (c.size() > 0) y.row(energy.free_vertices()[a]) += c.segment<3>(3 * a).transpose();
  }
  return y;
}

// Largest relative change of an edge length from x to y.
double largest_stretch(const Garment& g, const MatrixX3d& x, const MatrixX3d& y) {
  double worst = 0.0;
  for (int t = 0; t < g.F.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = g.F(t, k), j = g.F(t, (k + 1) % 3);
      const double before = (x.row(i) - x.row(j)).norm(), after = (y.row(i) - y.row(j)).norm();
      worst = std::max(worst, std::abs(after / before - 1.0));
    }
  return worst;
}

// A 0.3 m sheet pinned along its top edge swings about that edge by theta: the straight step
// theta w x (p - o) stretches every edge across the axis by about theta^2 / 2; the rotation's
// second-order part theta^2 / 2 w x (w x (p - o)) is what StepCurvature returns (the targets
// fit together exactly and agree with the pins), and the curved step keeps the lengths to
// fourth order.
TEST(StepCurvature, SwingingSheetFollowsTheRotation) {
  const Garment g = test::square_panel(12, 0.3);
  const ClothModel model = test::cotton_model(g, test::top_row(g));
  const ClothEnergy energy(model);
  const StepCurvature curvature(model, energy);
  const Vector3d axis = Vector3d::UnitX(), origin(0.0, 0.3, 0.0);
  for (const double theta : {0.2, 0.1}) {
    const VectorXd dx = step_of(energy, g.V, [&](const Vector3d& p) { return Vector3d(theta * axis.cross(p - origin)); });
    const VectorXd c = curvature(g.V, dx);
    const VectorXd exact = step_of(energy, g.V, [&](const Vector3d& p) {
      return Vector3d(0.5 * theta * theta * axis.cross(axis.cross(p - origin)));
    });
    EXPECT_LE((c - exact).norm(), 1e-6 * exact.norm()) << "theta " << theta;
    const double straight = largest_stretch(g, g.V, moved_by(energy, g.V, dx, {}));
    const double curved = largest_stretch(g, g.V, moved_by(energy, g.V, dx, c));
    EXPECT_NEAR(straight, std::sqrt(1.0 + theta * theta) - 1.0, 1e-9);
    EXPECT_LE(curved, theta * theta * theta * theta) << "theta " << theta << ", straight " << straight;
  }
}

// With no pin at all the Laplacian is singular (constants); the fit ignores them, so an
// unpinned sheet turning in its own plane gets the rotation's second-order part up to a shift.
TEST(StepCurvature, UnpinnedSheetTurningInItsPlane) {
  const Garment g = test::square_panel(10, 0.3);
  const ClothModel model = test::cotton_model(g, {});
  const ClothEnergy energy(model);
  const StepCurvature curvature(model, energy);
  const double theta = 0.15;
  const Vector3d axis = Vector3d::UnitZ(), origin(0.1, 0.05, 0.0);
  const VectorXd dx = step_of(energy, g.V, [&](const Vector3d& p) { return Vector3d(theta * axis.cross(p - origin)); });
  const VectorXd c = curvature(g.V, dx);
  ASSERT_TRUE(c.allFinite());
  VectorXd exact = step_of(energy, g.V, [&](const Vector3d& p) { return Vector3d(0.5 * theta * theta * axis.cross(axis.cross(p - origin))); });
  const Vector3d shift = exact.segment<3>(0) - c.segment<3>(0);
  for (int a = 0; a < energy.free_count(); ++a) exact.segment<3>(3 * a) -= shift;
  EXPECT_LE((c - exact).norm(), 1e-6 * exact.norm());
}

// A step with no gradient (a translation) stretches nothing and needs no curvature.
TEST(StepCurvature, TranslationIsStraight) {
  const Garment g = test::square_panel(6, 0.3);
  const ClothModel model = test::cotton_model(g, {});
  const ClothEnergy energy(model);
  const StepCurvature curvature(model, energy);
  const VectorXd dx = step_of(energy, g.V, [](const Vector3d&) { return Vector3d(0.01, -0.02, 0.005); });
  EXPECT_LE(curvature(g.V, dx).norm(), 1e-12);
}

// Drape triangles collapsed to a segment or a point have no plane to restore a strain in: they
// set no target, and the result stays finite.
TEST(StepCurvature, CollapsedDrapeTrianglesStayFinite) {
  const Garment g = test::square_panel(6, 0.3);
  const ClothModel model = test::cotton_model(g, test::top_row(g));
  const ClothEnergy energy(model);
  const StepCurvature curvature(model, energy);
  MatrixX3d x = g.V;
  x.row(8) = x.row(9);                          // two vertices on one point
  x.row(15) = 0.5 * (x.row(14) + x.row(16));    // three on one line
  const VectorXd dx = step_of(energy, x, [](const Vector3d& p) { return Vector3d(0.0, 0.0, 0.3 * p.x() * p.y()); });
  const VectorXd c = curvature(x, dx);
  EXPECT_TRUE(c.allFinite());
  EXPECT_GT(c.norm(), 0.0);
}

} // namespace
} // namespace foldsketch
