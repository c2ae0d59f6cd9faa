#include "mesh/isotropic_mesh.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "formats/body_mesh.h"
#include "garment/seams.h"
#include "mesh/triangle_geometry.h"
#include "samples/sample_scenes.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

double polygon_area(const MatrixX2d& O) {
  double a = 0;
  for (int i = 0; i < O.rows(); ++i) a += O(i, 0) * O((i + 1) % O.rows(), 1) - O((i + 1) % O.rows(), 0) * O(i, 1);
  return a / 2;
}

// Every outline vertex kept, in order and used; triangles counter-clockwise and not degenerate;
// together they cover exactly the polygon.
void expect_sound(const MatrixX2d& outline, double spacing) {
  const PlanarMesh m = isotropic_mesh(outline, spacing);
  ASSERT_GE(m.P.rows(), outline.rows());
  EXPECT_EQ(m.P.topRows(outline.rows()), outline);
  const VectorXd area = double_areas(m.P, m.F) / 2;
  EXPECT_GT(area.minCoeff(), 1e-6 * spacing * spacing) << "degenerate or clockwise triangle";
  EXPECT_NEAR(area.sum(), polygon_area(outline), 1e-9 * polygon_area(outline));
  std::vector<bool> used(static_cast<size_t>(m.P.rows()), false);
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<size_t>(m.F(f, k))] = true;
  for (int v = 0; v < m.P.rows(); ++v) EXPECT_TRUE(used[static_cast<size_t>(v)]) << "vertex " << v << " unused";
  EXPECT_GT(min_angles(m.P, m.F).minCoeff() * 180 / M_PI, 15.0);
}

MatrixX2d sampled_polygon(const std::vector<Vector2d>& corners, double spacing, double turn) {
  const Eigen::Rotation2Dd rotation(turn);
  std::vector<Vector2d> points;
  for (size_t c = 0; c < corners.size(); ++c) {
    const Vector2d a = corners[c], b = corners[(c + 1) % corners.size()];
    const int count = std::max(1, static_cast<int>(std::lround((b - a).norm() / spacing)));
    // Interpolated, then rotated: straight only up to roundoff, as unrolled seams are.
    for (int k = 0; k < count; ++k) points.push_back(rotation * ((1.0 - double(k) / count) * a + double(k) / count * b));
  }
  MatrixX2d O(static_cast<long>(points.size()), 2);
  for (size_t i = 0; i < points.size(); ++i) O.row(static_cast<long>(i)) = points[i].transpose();
  return O;
}

TEST(IsotropicMesh, RectangleAndRoundoffStraightOutlines) {
  expect_sound(sampled_polygon({{0, 0}, {1, 0}, {1, 0.6}, {0, 0.6}}, 0.02, 0.0), 0.02);
  for (const double turn : {0.3, 1.1, 2.9}) expect_sound(sampled_polygon({{0, 0}, {1, 0}, {1, 0.6}, {0, 0.6}}, 0.02, turn), 0.02);
}

TEST(IsotropicMesh, UnrolledConePanelOutlines) {
  const TriangleMesh body = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  SampleParams params;
  params.triangles = 5000;
  for (const char* name : {"skirt", "dress"}) {
    const Garment g = make_sample(name, params, &body.V).garment;
    for (const BoundaryLoop& loop : panel_boundaries(g)) {
      MatrixX2d O(static_cast<long>(loop.vertices.size()), 2);
      for (size_t i = 0; i < loop.vertices.size(); ++i) O.row(static_cast<long>(i)) = g.P.row(loop.vertices[i]);
      expect_sound(O, 0.02);
    }
  }
}

} // namespace
} // namespace foldsketch
