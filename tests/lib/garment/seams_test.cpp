#include "garment/seams.h"

#include <gtest/gtest.h>

#include "garment/garment_issues.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(Seams, TwoWeldedSquaresShareOneSeam) {
  const Garment g = test::two_sewn_squares();
  ASSERT_EQ(garment_structure_error(g), "");
  const auto loops = panel_boundaries(g);
  ASSERT_EQ(loops.size(), 2u);
  const auto s = seams(g, loops);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_FALSE(s[0].closed);
  EXPECT_NE(s[0].a.panel, s[0].b.panel);
  ASSERT_EQ(s[0].a.vertices.size(), 2u);
  const VectorXi drape = pattern_to_drape(g);
  for (size_t i = 0; i < 2; ++i) EXPECT_EQ(drape(s[0].a.vertices[i]), drape(s[0].b.vertices[i]));
  EXPECT_DOUBLE_EQ(pattern_length(g.P, s[0].a.vertices), 1.0);
  EXPECT_DOUBLE_EQ(pattern_length(g.P, s[0].b.vertices), 1.0);
  EXPECT_DOUBLE_EQ(drape_length(g, s[0].a.vertices), 1.0);
}

TEST(Seams, TubeSewnToItselfHasOneSelfSeam) {
  // A 4 x 2 strip rolled so its left and right edges weld.
  Garment g = test::square_panel(4, 1.0);
  const int n = 4;
  for (int j = 0; j <= n; ++j) {
    const int right = j * (n + 1) + n, left = j * (n + 1);
    for (int f = 0; f < g.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (g.F(f, k) == right) g.F(f, k) = left;
  }
  const auto s = seams(g, panel_boundaries(g));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].a.panel, s[0].b.panel);
  EXPECT_EQ(s[0].a.vertices.size(), 5u);
  EXPECT_DOUBLE_EQ(pattern_length(g.P, s[0].a.vertices), pattern_length(g.P, s[0].b.vertices));
}

TEST(Seams, ThreePanelsOnOneEdgeAreNotSewnButReported) {
  Garment g = test::two_sewn_squares();
  // A third panel (one triangle) on drape edge 1-4.
  g.V.conservativeResize(7, 3);
  g.V.row(6) << 1, 0.5, 1;
  g.P.conservativeResize(11, 2);
  g.P.bottomRows(3) << 6, 0, 7, 0, 6, 1;
  g.F.conservativeResize(5, 3);
  g.F.row(4) << 4, 1, 6;
  g.FP.conservativeResize(5, 3);
  g.FP.row(4) << 8, 9, 10;
  g.face_panel.conservativeResize(5);
  g.face_panel(4) = 2;
  g.panels.push_back({"third"});
  ASSERT_EQ(garment_structure_error(g), "");
  EXPECT_TRUE(seams(g, panel_boundaries(g)).empty());
  EXPECT_EQ(garment_issues(g).nonmanifold_drape_edges.size(), 1u);
}

TEST(Seams, WholeLoopsSewnTogetherMakeAClosedSeam) {
  // Two triangles' outlines sewn edge to edge: a (flat, doubled) closed bag.
  Garment g;
  g.V.resize(3, 3);
  g.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  g.P.resize(6, 2);
  g.P << 0, 0, 1, 0, 0, 1, 3, 0, 2, 0, 3, 1;
  g.F.resize(2, 3);
  g.F << 0, 1, 2, 0, 2, 1;
  g.FP.resize(2, 3);
  g.FP << 0, 1, 2, 3, 5, 4;
  g.face_panel.resize(2);
  g.face_panel << 0, 1;
  g.panels = {{"front"}, {"back"}};
  const auto s = seams(g, panel_boundaries(g));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_TRUE(s[0].closed);
  EXPECT_EQ(s[0].a.vertices.size(), 3u);
  EXPECT_NEAR(pattern_length(g.P, s[0].a.vertices, true), 2 + std::sqrt(2.0), 1e-12);
}

} // namespace
} // namespace foldsketch
