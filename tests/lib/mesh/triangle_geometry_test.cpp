#include "mesh/triangle_geometry.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace foldsketch {
namespace {

class RightTriangle : public ::testing::TestWithParam<double> {};

// The 3-4-5 triangle at every scale from 1e-8 to 1e8: measures scale exactly as they should.
TEST_P(RightTriangle, MeasuresScaleWithSize) {
  const double s = GetParam();
  MatrixX2d P(3, 2);
  P << 0, 0, 4 * s, 0, 0, 3 * s;
  MatrixX3i F(1, 3);
  F << 0, 1, 2;
  EXPECT_NEAR(double_areas(P, F)(0), 12 * s * s, 1e-14 * 12 * s * s);
  const MatrixX3d L = edge_lengths(P, F);
  EXPECT_NEAR(L(0, 0), 5 * s, 1e-14 * 5 * s);
  EXPECT_NEAR(L(0, 1), 3 * s, 1e-14 * 3 * s);
  EXPECT_NEAR(L(0, 2), 4 * s, 1e-14 * 4 * s);
  const MatrixX3d A = internal_angles(P, F);
  EXPECT_NEAR(A(0, 0), std::numbers::pi / 2, 1e-14);
  EXPECT_NEAR(A(0, 1), std::atan2(3.0, 4.0), 1e-14);
  EXPECT_NEAR(A.row(0).sum(), std::numbers::pi, 1e-14);
  MatrixX3d V(3, 3);
  V << 0, 0, 0, 0, 4 * s, 0, 0, 0, 3 * s;
  EXPECT_NEAR(double_areas(V, F)(0), 12 * s * s, 1e-14 * 12 * s * s);
}
INSTANTIATE_TEST_SUITE_P(Scales, RightTriangle, ::testing::Values(1e-8, 1e-3, 1.0, 1e3, 1e8));

TEST(TriangleGeometry, ClockwiseTriangleHasNegativeSignedArea) {
  MatrixX2d P(3, 2);
  P << 0, 0, 0, 1, 1, 0;
  MatrixX3i F(1, 3);
  F << 0, 1, 2;
  EXPECT_DOUBLE_EQ(double_areas(P, F)(0), -1.0);
}

TEST(TriangleGeometry, SliverAngleIsAccurate) {
  // A needle with a 1e-9 rad angle: acos-based formulas lose it entirely.
  MatrixX2d P(3, 2);
  P << 0, 0, 1, 0, 1, 1e-9;
  MatrixX3i F(1, 3);
  F << 0, 1, 2;
  EXPECT_NEAR(min_angles(P, F)(0), 1e-9, 1e-18);
}

TEST(TriangleGeometry, CollapsedTriangleIsReportedNotCrashed) {
  MatrixX2d P(3, 2);
  P << 0, 0, 0, 0, 1, 0;
  MatrixX3i F(1, 3);
  F << 0, 1, 2;
  EXPECT_EQ(min_angles(P, F)(0), 0.0);
  EXPECT_EQ(double_areas(P, F)(0), 0.0);
}

} // namespace
} // namespace foldsketch
