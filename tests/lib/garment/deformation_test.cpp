#include "garment/deformation.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(Deformation, RigidPlacementHasUnitStretches) {
  Garment g = test::square_panel(3, 0.7);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.8, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  g.V = (g.V * R.transpose()).rowwise() + Eigen::RowVector3d(5, -2, 1);
  const MatrixX2d S = principal_stretches(g);
  EXPECT_NEAR((S.array() - 1.0).abs().maxCoeff(), 0.0, 1e-12);
}

TEST(Deformation, StretchAlongXIsRecovered) {
  Garment g = test::square_panel(3, 1.0);
  g.V.col(0) *= 1.25;
  const auto D = deformation_gradients(g);
  for (const Matrix32d& d : D) {
    EXPECT_NEAR(d(0, 0), 1.25, 1e-12);
    EXPECT_NEAR(d(1, 1), 1.0, 1e-12);
    EXPECT_NEAR(d(0, 1), 0.0, 1e-12);
  }
  const MatrixX2d S = principal_stretches(g);
  EXPECT_NEAR(S.col(0).maxCoeff(), 1.25, 1e-12);
  EXPECT_NEAR(S.col(1).minCoeff(), 1.0, 1e-12);
}

TEST(Deformation, ZeroAreaRestTriangleGivesNaNNotACrash) {
  Garment g = test::square_panel(1);
  g.P.row(2) = g.P.row(0);  // collapses triangle 1 = (0, 3, 2)
  const auto D = deformation_gradients(g);
  EXPECT_TRUE(D[0].allFinite());
  EXPECT_FALSE(D[1].allFinite());
}

} // namespace
} // namespace foldsketch
