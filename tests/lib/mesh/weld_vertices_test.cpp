#include "mesh/weld_vertices.h"

#include <gtest/gtest.h>

namespace foldsketch {
namespace {

TEST(WeldVertices, MergesNearbyRowsAcrossCellBoundaries) {
  MatrixX3d V(5, 3);
  // Rows 0 and 2 straddle a hashing cell boundary (x = 0 with tolerance 1e-6).
  V << -1e-9, 0, 0, 1, 1, 1, 1e-9, 0, 0, 1, 1, 1 + 5e-7, 2, 0, 0;
  const VectorXi w = weld_vertices(V, 1e-6);
  EXPECT_EQ(w(0), w(2));
  EXPECT_EQ(w(1), w(3));
  EXPECT_EQ(w(4), 2);
  const MatrixX3d W = welded_positions(V, w);
  ASSERT_EQ(W.rows(), 3);
  EXPECT_EQ(W(0, 0), -1e-9);  // first row wins
}

TEST(WeldVertices, KeepsDistinctRows) {
  MatrixX3d V(2, 3);
  V << 0, 0, 0, 2e-6, 0, 0;
  const VectorXi w = weld_vertices(V, 1e-6);
  EXPECT_NE(w(0), w(1));
}

} // namespace
} // namespace foldsketch
