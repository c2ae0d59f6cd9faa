#include "garment/boundary_runs.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(BoundaryRuns, SquareHasFourCornersAndFourSides) {
  const Garment g = test::square_panel(5, 0.5);
  const auto loops = panel_boundaries(g);
  const auto corners = boundary_corners(g, loops, {});
  ASSERT_EQ(corners[0].size(), 4u);
  const auto runs = boundary_runs(loops, corners);
  ASSERT_EQ(runs.size(), 4u);
  for (const BoundaryRun& r : runs) {
    EXPECT_EQ(r.vertices.size(), 6u);
    EXPECT_NEAR(pattern_length(g.P, r.vertices), 0.5, 1e-12);
  }
}

TEST(BoundaryRuns, SeamEndsAreCorners) {
  // Two squares sewn along an edge: each square's outline is split at the seam ends anyway
  // (they are square corners), and the seam side is one run.
  const Garment g = test::two_sewn_squares();
  const auto loops = panel_boundaries(g);
  const auto s = seams(g, loops);
  const auto runs = boundary_runs(loops, boundary_corners(g, loops, s));
  EXPECT_EQ(runs.size(), 8u);
}

TEST(BoundaryRuns, SmoothCurveWithoutCornersIsOneClosedRun) {
  // A regular 64-gon fan: turning 5.6 degrees per vertex, below the corner threshold.
  const int n = 64;
  Garment g;
  g.P.resize(n + 1, 2);
  g.V.resize(n + 1, 3);
  g.P.row(n) << 0, 0;
  for (int i = 0; i < n; ++i) g.P.row(i) << std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n);
  g.V << g.P, VectorXd::Zero(n + 1);
  g.F.resize(n, 3);
  for (int i = 0; i < n; ++i) g.F.row(i) << n, i, (i + 1) % n;
  g.FP = g.F;
  g.face_panel = VectorXi::Zero(n);
  g.panels = {{"disc"}};
  const auto loops = panel_boundaries(g);
  const auto runs = boundary_runs(loops, boundary_corners(g, loops, {}));
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_TRUE(runs[0].closed);
}

} // namespace
} // namespace foldsketch
