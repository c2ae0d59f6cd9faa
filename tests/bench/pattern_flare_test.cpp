// The benchmark's flare (bench/pattern_flare.h): zero is no change; the outer quarters of each
// panel turn rigidly, so seams keep their lengths; inside the middle half the map's area
// factor is exactly 1 + flare |v| / L (v the depth below the panel's top, L its height). A
// straight-edged triangle's area follows it up to a term first order in the triangle's size,
// of alternating sign (about 1 % on this 1500-triangle skirt), so the band's total follows it
// far closer.
#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "garment/seams.h"
#include "pattern_flare.h"
#include "samples/sample_scenes.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// The skirt sample at 1500 triangles on the committed body, built once for these tests.
const Garment& small_skirt() {
  static const Garment skirt = [] {
    const TriangleMesh body = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
    SampleParams params;
    params.triangles = 1500;
    return make_sample("skirt", params, &body.V).garment;
  }();
  return skirt;
}

double signed_area(const MatrixX2d& P, const MatrixX3i& FP, int f) {
  const Eigen::Vector2d a = P.row(FP(f, 1)) - P.row(FP(f, 0)), b = P.row(FP(f, 2)) - P.row(FP(f, 0));
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

TEST(PatternFlare, ZeroFlareLeavesThePatternsAlone) {
  const Garment& g = small_skirt();
  const Garment h = flared_patterns(g, 0.0);
  EXPECT_LT((h.P - g.P).cwiseAbs().maxCoeff(), 1e-15);  // rounding of (x - x_c) + x_c only
  EXPECT_TRUE(h.V == g.V && h.F == g.F && h.FP == g.FP);
}

TEST(PatternFlare, SeamsKeepTheirLengthsAndStillMatch) {
  const Garment& g = small_skirt();
  const Garment h = flared_patterns(g, 0.4);
  const auto loops = panel_boundaries(g);
  const auto sewn = seams(g, loops);
  ASSERT_EQ(sewn.size(), 2u);  // the two side seams
  for (const Seam& s : sewn) {
    const double before = pattern_length(g.P, s.a.vertices);
    EXPECT_NEAR(pattern_length(h.P, s.a.vertices), before, 1e-12);
    EXPECT_NEAR(pattern_length(h.P, s.b.vertices), pattern_length(g.P, s.b.vertices), 1e-12);
  }
  EXPECT_TRUE(h.V == g.V);
}

TEST(PatternFlare, TheMiddleHalfFansOutByTheFlareAtTheHem) {
  const Garment& g = small_skirt();
  const double flare = 0.4;
  const Garment h = flared_patterns(g, flare);
  int inside = 0, outside = 0;
  double widest = 0.0;                   // largest |v| / L of an inside triangle checked
  double band_after = 0.0, band_expected = 0.0;  // the middle half's triangles' total area
  for (int p = 0; p < static_cast<int>(g.panels.size()); ++p) {
    const auto faces = panel_faces(g, p);
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (int f : faces)
      for (int k = 0; k < 3; ++k) {
        const int i = g.FP(f, k);
        x0 = std::min(x0, g.P(i, 0)), x1 = std::max(x1, g.P(i, 0));
        y0 = std::min(y0, g.P(i, 1)), y1 = std::max(y1, g.P(i, 1));
      }
    const double xc = 0.5 * (x0 + x1), half_band = 0.25 * (x1 - x0), height = y1 - y0;
    for (int f : faces) {
      double umin = 1e9, umax = -1e9, depth = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double u = g.P(g.FP(f, k), 0) - xc;
        umin = std::min(umin, u), umax = std::max(umax, u);
        depth += (y1 - g.P(g.FP(f, k), 1)) / 3.0;
      }
      const double ratio = signed_area(h.P, h.FP, f) / signed_area(g.P, g.FP, f);
      if (umin >= half_band || umax <= -half_band) {  // an outer quarter: turned rigidly
        ++outside;
        EXPECT_NEAR(ratio, 1.0, 1e-12);
      } else if (umin > -half_band && umax < half_band) {  // the middle half: fanned out
        ++inside;
        EXPECT_NEAR(ratio, 1.0 + flare * depth / height, 0.02) << "triangle " << f;
        band_after += signed_area(h.P, h.FP, f);
        band_expected += (1.0 + flare * depth / height) * signed_area(g.P, g.FP, f);
        widest = std::max(widest, depth / height);
      }
    }
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(outside, 300);
  EXPECT_GT(widest, 0.9);  // the check reached the hem
  EXPECT_NEAR(band_after / band_expected, 1.0, 1e-3);
}

TEST(PatternFlare, RefusesANegativeFlare) {
  EXPECT_THROW(flared_patterns(small_skirt(), -0.1), ArgumentError);
}

} // namespace
} // namespace foldsketch
