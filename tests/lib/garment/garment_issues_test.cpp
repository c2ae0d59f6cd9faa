#include "garment/garment_issues.h"

#include <limits>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(GarmentIssues, CleanPanelHasNone) {
  const GarmentIssues issues = garment_issues(test::square_panel(3));
  EXPECT_TRUE(issues.empty()) << ::testing::PrintToString(issues.messages());
}

TEST(GarmentIssues, DegenerateTriangleIsReportedNotThrown) {
  Garment g = test::square_panel(2);
  g.P.row(4) = g.P.row(0);  // collapse the centre vertex onto a corner
  GarmentIssues issues;
  ASSERT_NO_THROW(issues = garment_issues(g));
  EXPECT_FALSE(issues.degenerate_pattern_faces.empty());
  EXPECT_FALSE(issues.messages().empty());
}

TEST(GarmentIssues, PatternsInOtherUnitsThanTheDrapeAreReported) {
  Garment g = test::square_panel(3);
  g.P *= 1000.0;  // millimetres against the drape's metres
  const GarmentIssues issues = garment_issues(g);
  EXPECT_FALSE(issues.empty());
  ASSERT_EQ(issues.messages().size(), 1u);
  EXPECT_EQ(issues.messages()[0].rfind("the drape is 0.001 times the size of its patterns", 0), 0u) << issues.messages()[0];
}

TEST(GarmentIssues, SliverIsReported) {
  Garment g = test::square_panel(1);
  g.P.row(3) << 0.05, 1.0;  // triangle (0, 3, 2) becomes a 2.9-degree sliver
  const GarmentIssues issues = garment_issues(g);
  EXPECT_EQ(issues.sliver_pattern_faces.size(), 1u);
  EXPECT_TRUE(issues.degenerate_pattern_faces.empty());
}

TEST(GarmentIssues, FlippedTriangleIsReported) {
  Garment g = test::square_panel(3);
  std::swap(g.FP(0, 1), g.FP(0, 2));
  std::swap(g.F(0, 1), g.F(0, 2));
  const GarmentIssues issues = garment_issues(g);
  ASSERT_EQ(issues.flipped_pattern_faces.size(), 1u);
  EXPECT_EQ(issues.flipped_pattern_faces[0], 0);
  EXPECT_FALSE(issues.misoriented_drape_edges.empty());
}

TEST(GarmentIssues, NonFiniteCoordinatesAreReported) {
  Garment g = test::square_panel(2);
  g.V(3, 1) = std::numeric_limits<double>::quiet_NaN();
  g.P(2, 0) = std::numeric_limits<double>::infinity();
  const GarmentIssues issues = garment_issues(g);
  EXPECT_EQ(issues.nonfinite_drape_vertices, std::vector<int>{3});
  EXPECT_EQ(issues.nonfinite_pattern_vertices, std::vector<int>{2});
}

TEST(GarmentStructure, NamesWhatIsWrong) {
  Garment g = test::square_panel(2);
  EXPECT_EQ(garment_structure_error(g), "");
  Garment bad = g;
  bad.F(0, 0) = 100;
  EXPECT_NE(garment_structure_error(bad).find("drape vertex"), std::string::npos);
  bad = g;
  bad.F(1, 0) = 8;  // pattern vertex 0 now used with two drape vertices
  EXPECT_NE(garment_structure_error(bad).find("pattern vertex 1"), std::string::npos);
  bad = g;
  bad.stitches.push_back({{0, -1, 0}, {99, -1, 0}});
  EXPECT_NE(garment_structure_error(bad).find("stitch 1"), std::string::npos);
}

} // namespace
} // namespace foldsketch
