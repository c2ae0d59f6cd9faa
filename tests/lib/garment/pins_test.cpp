#include "garment/pins.h"

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

} // namespace
} // namespace foldsketch
