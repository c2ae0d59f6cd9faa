#include "sim/material.h"

#include <gtest/gtest.h>

namespace foldsketch {
namespace {

TEST(Material, EveryPresetIsUsableAndCited) {
  for (const std::string& name : material_preset_names()) {
    const auto m = material_preset(name);
    ASSERT_TRUE(m) << name;
    EXPECT_EQ(material_error(*m), "") << name;
    EXPECT_FALSE(m->source.empty()) << name;
    // Bending lengths of garment fabrics lie between about 0.5 and 3 cm (Peirce); the
    // measured trouser twill (royal-target) reaches 4.3 cm.
    EXPECT_GT(m->bending_length(), 0.005) << name;
    EXPECT_LT(m->bending_length(), 0.045) << name;
  }
  EXPECT_FALSE(material_preset("velvet"));
}

TEST(Material, PenavaCottonGivesTheMeasuredStiffness) {
  const Material m = *material_preset("cotton-thin");
  EXPECT_NEAR(m.stretch_warp, 261.0, 0.5);  // E t = 0.821 MPa x 0.318 mm
  EXPECT_DOUBLE_EQ(m.density, 0.150);
}

TEST(Material, BendingLengthOrderMatchesTheFabrics) {
  const auto c = [](const char* n) { return material_preset(n)->bending_length(); };
  EXPECT_LT(c("silk"), c("cotton-thin"));
  EXPECT_LT(c("cotton-thin"), c("denim"));
  EXPECT_LT(c("denim"), c("leather"));
}

TEST(Material, ErrorsNameTheBadValue) {
  Material m = *material_preset("denim");
  m.density = -1;
  EXPECT_NE(material_error(m).find("density"), std::string::npos);
  m = *material_preset("denim");
  m.poisson = 0.7;
  EXPECT_NE(material_error(m).find("Poisson"), std::string::npos);
}

} // namespace
} // namespace foldsketch
