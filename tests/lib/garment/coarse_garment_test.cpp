#include "garment/coarse_garment.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"
#include "garment/seams.h"
#include "mesh/triangle_geometry.h"
#include "samples/sample_scenes.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// Signed: every triangle is counter-clockwise (checked below), so it is the area.
double pattern_area(const Garment& g) { return 0.5 * double_areas(g.P, g.FP).sum(); }

// Checks shared by the samples: sound structure, the same panels and seams, the triangle count
// near the target, and the kept outline vertices exactly where they were in the drape.
void expect_coarse_version(const Garment& fine, const Garment& coarse, int triangles) {
  ASSERT_EQ(garment_structure_error(coarse), "");
  EXPECT_EQ(coarse.panels, fine.panels);
  EXPECT_NEAR(static_cast<double>(coarse.F.rows()), triangles, 0.25 * triangles);
  // Every triangle counter-clockwise in the pattern, so the signed area is the area; it keeps
  // the fine patterns' area up to the chords cut off curved outlines.
  const VectorXd areas = double_areas(coarse.P, coarse.FP);
  for (int f = 0; f < coarse.FP.rows(); ++f) ASSERT_GT(areas(f), 0.0) << "triangle " << f;
  EXPECT_NEAR(pattern_area(coarse), pattern_area(fine), 0.01 * pattern_area(fine));

  const std::vector<Seam> fine_seams = seams(fine, panel_boundaries(fine));
  const std::vector<Seam> coarse_seams = seams(coarse, panel_boundaries(coarse));
  ASSERT_EQ(coarse_seams.size(), fine_seams.size());
  for (size_t s = 0; s < fine_seams.size(); ++s) {
    EXPECT_EQ(coarse_seams[s].a.panel, fine_seams[s].a.panel);
    EXPECT_EQ(coarse_seams[s].b.panel, fine_seams[s].b.panel);
    EXPECT_NEAR(pattern_length(coarse.P, coarse_seams[s].a.vertices, coarse_seams[s].closed),
                pattern_length(fine.P, fine_seams[s].a.vertices, fine_seams[s].closed),
                0.01 * pattern_length(fine.P, fine_seams[s].a.vertices, fine_seams[s].closed));
  }
  // Outline vertices are original ones: each sits on an original drape vertex.
  const VectorXi drape = pattern_to_drape(coarse);
  for (const BoundaryLoop& loop : panel_boundaries(coarse))
    for (int v : loop.vertices) {
      const Eigen::RowVector3d x = coarse.V.row(drape(v));
      double nearest = INFINITY;
      for (int w = 0; w < fine.V.rows(); ++w) nearest = std::min(nearest, (fine.V.row(w) - x).squaredNorm());
      ASSERT_LT(nearest, 1e-24) << "outline vertex " << v;
    }
}

TEST(CoarseGarment, KeepsTheBoxCoversPanelsSewnAlongEveryEdge) {
  SampleParams params;
  params.triangles = 8000;
  const Garment fine = make_sample("box-cover", params).garment;
  const Garment coarse = coarse_garment(fine, spacing_for_triangles(fine, 1000));
  expect_coarse_version(fine, coarse, 1000);
}

TEST(CoarseGarment, KeepsTheSkirtsCurvedSeamsSewn) {
  const Garment fine = test::skirt_on_body(10000).skirt.garment;
  const Garment coarse = coarse_garment(fine, spacing_for_triangles(fine, 2500));
  expect_coarse_version(fine, coarse, 2500);
}

TEST(CoarseGarment, CarriesAnAffineDrapeExactly) {
  Garment fine = test::square_panel(40, 1.0);
  Eigen::Matrix<double, 2, 3> A;
  A << 0.3, -0.7, 0.2, 0.5, 0.1, -0.9;
  for (int f = 0; f < fine.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) fine.V.row(fine.F(f, k)) = fine.P.row(fine.FP(f, k)) * A;
  const Garment coarse = coarse_garment(fine, 0.1);
  expect_coarse_version(fine, coarse, static_cast<int>(1.0 / (std::sqrt(3.0) / 4 * 0.01)));
  for (int f = 0; f < coarse.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((coarse.V.row(coarse.F(f, k)) - coarse.P.row(coarse.FP(f, k)) * A).norm(), 1e-12);
}

TEST(CoarseGarment, KeepsHoles) {
  MatrixX2d outline(4, 2), hole(4, 2);
  outline << 0, 0, 1, 0, 1, 1, 0, 1;
  hole << 0.4, 0.4, 0.6, 0.4, 0.6, 0.6, 0.4, 0.6;
  const Garment fine = test::polygon_panel("holed", outline, 0.01, {hole});
  const Garment coarse = coarse_garment(fine, 0.05);
  EXPECT_EQ(panel_boundaries(coarse).size(), 2u);
  EXPECT_NEAR(pattern_area(coarse), 0.96, 1e-9);
}

TEST(CoarseGarment, KeepsAtLeastATriangleOfEveryOutline) {
  // A half disc: two corners, so the arc keeps a vertex inside however coarse (the diameter is
  // one edge of the original outline, so it keeps none).
  MatrixX2d outline(33, 2);
  for (int k = 0; k <= 32; ++k) outline.row(k) << std::cos(M_PI * k / 32), std::sin(M_PI * k / 32);
  const Garment fine = test::polygon_panel("half disc", outline, 0.05);
  const Garment coarse = coarse_garment(fine, 10.0);
  ASSERT_EQ(garment_structure_error(coarse), "");
  EXPECT_EQ(panel_boundaries(coarse)[0].vertices.size(), 3u);
  EXPECT_EQ(coarse.F.rows(), 1);
}

TEST(CoarseGarment, RefusesStitchesAndBadSpacings) {
  Garment g = test::two_sewn_squares();
  EXPECT_THROW(coarse_garment(g, 0.0), ArgumentError);
  g.stitches.push_back({{0, -1, 0.0}, {1, -1, 0.0}});
  EXPECT_THROW(coarse_garment(g, 0.1), ArgumentError);
}

} // namespace
} // namespace foldsketch
