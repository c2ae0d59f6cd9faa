#include "garment/drape_scale.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(DrapeScale, DrapeAtItsPatternSizeIsOne) {
  const Garment g = test::square_panel(3);
  EXPECT_NEAR(median_drape_scale(g), 1.0, 1e-12);
  EXPECT_EQ(drape_scale_error(g), "");
}

// The Berkeley Garment Library skirt's placement stretches triangles by 0.58-1.45 per
// direction: a drape distorted that much is no units mistake.
TEST(DrapeScale, DistortedPlacementPasses) {
  Garment g = test::square_panel(4);
  g.V.col(0) *= 1.45;
  g.V.col(1) *= 0.58;
  EXPECT_NEAR(median_drape_scale(g), std::sqrt(1.45 * 0.58), 1e-12);
  EXPECT_EQ(drape_scale_error(g), "");
}

TEST(DrapeScale, PatternsInMillimetresOrCentimetresAreRefusedWithTheirFactor) {
  Garment mm = test::square_panel(3);
  mm.P *= 1000.0;
  EXPECT_NEAR(median_drape_scale(mm), 0.001, 1e-15);
  const std::string error = drape_scale_error(mm);
  EXPECT_NE(error.find("the drape is 0.001 times the size of its patterns"), std::string::npos) << error;
  EXPECT_NE(error.find("metres"), std::string::npos) << error;
  Garment cm = test::square_panel(3);
  cm.P *= 0.01;  // a drape in centimetres against patterns in metres: 100 times larger
  EXPECT_NE(drape_scale_error(cm).find("the drape is 100 times"), std::string::npos) << drape_scale_error(cm);
}

TEST(DrapeScale, DegenerateTrianglesAreLeftOut) {
  Garment g = test::square_panel(3);
  g.P *= 1000.0;
  g.V.row(g.F(0, 1)) = g.V.row(g.F(0, 0));  // one triangle collapsed in the drape
  EXPECT_NEAR(median_drape_scale(g), 0.001, 1e-15);
  Garment empty = test::square_panel(1);
  empty.V.setZero();
  EXPECT_TRUE(std::isnan(median_drape_scale(empty)));
  EXPECT_EQ(drape_scale_error(empty), "");  // nothing to judge: other checks speak
}

} // namespace
} // namespace foldsketch
