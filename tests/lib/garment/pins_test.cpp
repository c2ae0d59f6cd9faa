#include "garment/pins.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(Pins, BoxSelectsTheEdgeOfAPanel) {
  const Garment g = test::square_panel(4, 1.0);
  const auto left = vertices_in_box(g.V, Eigen::AlignedBox3d(Vector3d(-1e-6, -1, -1), Vector3d(1e-6, 2, 1)));
  EXPECT_EQ(left, (std::vector<int>{0, 5, 10, 15, 20}));
  const auto pins = pins_at(g.V, {10, 0, 10});
  ASSERT_EQ(pins.size(), 2u);
  EXPECT_EQ(pins[1].vertex, 10);
  EXPECT_EQ(pins[1].position, Vector3d(0, 0.5, 0));
}

TEST(Pins, MostStretchedPinnedEdgeIsTheLongestAgainstItsPattern) {
  Garment g = test::square_panel(2, 1.0);  // vertices 0-2 the bottom row, 6-8 the top one
  EXPECT_EQ(most_stretched_pinned_edge(g, {}).v0, -1);
  EXPECT_EQ(most_stretched_pinned_edge(g, {0, 8}).v0, -1);  // no edge joins them
  g.V(2, 0) = 2.5;  // the bottom row's right edge, 0.5 m in the pattern, now 2 m long
  const PinnedEdge e = most_stretched_pinned_edge(g, {0, 1, 2});
  EXPECT_EQ(std::minmax(e.v0, e.v1), std::minmax(1, 2));
  EXPECT_DOUBLE_EQ(e.stretch, 4.0);
  const PinnedEdge at_rest = most_stretched_pinned_edge(g, {6, 7, 8});
  EXPECT_NE(at_rest.v0, -1);
  EXPECT_DOUBLE_EQ(at_rest.stretch, 1.0);
}

} // namespace
} // namespace foldsketch
