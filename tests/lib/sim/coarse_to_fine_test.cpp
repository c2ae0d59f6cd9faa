#include "sim/coarse_to_fine.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(CoarseLevels, QuarterTheTrianglesDownToTheSmallestLevel) {
  EXPECT_EQ(coarse_levels(20000), (std::vector<int>{5000}));
  EXPECT_EQ(coarse_levels(54000), (std::vector<int>{3375, 13500}));
  EXPECT_EQ(coarse_levels(10000), (std::vector<int>{2500}));
  EXPECT_TRUE(coarse_levels(7000).empty());
}

// The skirt, cold from its sewn placement, through a coarse level: the garment's own mesh ends
// at the same standard as a plain drape (the tolerance, pins exact, clear of the body).
TEST(CoarseToFine, DrapesTheSkirtThroughACoarseLevel) {
  const test::SkirtOnBody s = test::skirt_on_body(3000);
  const DrapeSettings settings;
  const CoarseToFineResult r = solve_drape_coarse_to_fine(s.skirt.garment, s.skirt.scene, s.model,
                                                          s.skirt.garment.V, settings, {800});
  ASSERT_EQ(r.levels.size(), 2u);
  EXPECT_NEAR(r.levels[0].triangles, 800, 200);
  EXPECT_TRUE(r.levels[0].stats.converged);
  EXPECT_EQ(r.levels[1].triangles, static_cast<int>(s.model.triangles.size()));
  EXPECT_TRUE(r.drape.stats.converged) << r.drape.stats.message;
  EXPECT_LE(r.drape.stats.residual, settings.tolerance);
  EXPECT_LE(r.drape.stats.max_penetration, 0.5e-3);
  for (const Pin& p : s.model.pins) EXPECT_EQ(r.drape.V.row(p.vertex), p.position.transpose());
  EXPECT_GE(r.seconds_total, r.levels[0].stats.seconds_total + r.levels[1].stats.seconds_total);
}

TEST(CoarseToFine, RefusesSelfContact) {
  test::SkirtOnBody s = test::skirt_on_body(1000);
  s.skirt.scene.physics.self_contact = true;
  EXPECT_THROW(solve_drape_coarse_to_fine(s.skirt.garment, s.skirt.scene, s.model, s.skirt.garment.V, {}, {300}),
               ArgumentError);
}

} // namespace
} // namespace foldsketch
