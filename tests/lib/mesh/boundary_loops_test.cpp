#include "mesh/boundary_loops.h"

#include <gtest/gtest.h>

#include "garment/seams.h"
#include "mesh/triangle_geometry.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// Signed area of a closed polygon (positive when counter-clockwise).
double polygon_area(const MatrixX2d& P, const std::vector<int>& loop) {
  double a = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const auto p = P.row(loop[i]), q = P.row(loop[(i + 1) % loop.size()]);
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a / 2;
}

TEST(BoundaryLoops, SquareGridHasOneCounterClockwiseLoop) {
  const Garment g = test::square_panel(4, 2.0);
  const auto loops = boundary_loops(g.FP, static_cast<int>(g.P.rows()));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 16u);
  EXPECT_NEAR(polygon_area(g.P, loops[0]), 4.0, 1e-12);
  EXPECT_NEAR(pattern_length(g.P, loops[0], true), 8.0, 1e-12);
}

TEST(BoundaryLoops, HoleGivesASecondClockwiseLoop) {
  Garment g = test::square_panel(3, 3.0);
  // Remove the two triangles of the middle cell (cell index 4).
  MatrixX3i F(g.F.rows() - 2, 3);
  int r = 0;
  for (int f = 0; f < g.F.rows(); ++f)
    if (f / 2 != 4) F.row(r++) = g.F.row(f);
  const auto loops = boundary_loops(F, static_cast<int>(g.P.rows()));
  ASSERT_EQ(loops.size(), 2u);
  double outer = polygon_area(g.P, loops[0]), inner = polygon_area(g.P, loops[1]);
  if (outer < inner) std::swap(outer, inner);
  EXPECT_NEAR(outer, 9.0, 1e-12);
  EXPECT_NEAR(inner, -1.0, 1e-12);
}

TEST(BoundaryLoops, ClosedSurfaceHasNone) {
  MatrixX3i F(4, 3);  // tetrahedron
  F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  EXPECT_TRUE(boundary_loops(F, 4).empty());
}

} // namespace
} // namespace foldsketch
