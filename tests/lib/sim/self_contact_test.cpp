// Cloth-cloth contact: distances against brute force, the broad phase against all pairs, one
// acting pair per layer, the step bound against tunnelling, and seams left alone.
#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "samples/grid_garment.h"
#include "sim/cloth_model.h"
#include "sim/self_contact.h"

namespace foldsketch {
namespace {

Vector3d random_point(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  return {u(rng), u(rng), u(rng)};
}

TEST(SelfContact, DistancesMatchDenseSampling) {
  std::mt19937 rng(1);
  constexpr int kSamples = 400;
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3d p = random_point(rng, 1.0), a = random_point(rng, 1.0), b = random_point(rng, 1.0), c = random_point(rng, 1.0);
    double sampled = INFINITY;
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 0; i + j <= kSamples; ++j) {
        const double u = double(i) / kSamples, v = double(j) / kSamples;
        sampled = std::min(sampled, (p - ((1 - u - v) * a + u * b + v * c)).norm());
      }
    const double d = point_triangle_distance(p, a, b, c);
    EXPECT_LE(d, sampled + 1e-12);
    EXPECT_GE(d, sampled - 4.0 / kSamples);  // the grid's spacing on triangles of size ~2
    const Vector3d q = random_point(rng, 1.0);
    double segment_sampled = INFINITY;
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 0; j <= kSamples; ++j)
        segment_sampled = std::min(segment_sampled, ((p + (a - p) * i / kSamples) - (q + (b - q) * j / kSamples)).norm());
    const double s = segment_segment_distance(p, a, q, b);
    EXPECT_LE(s, segment_sampled + 1e-12);
    EXPECT_GE(s, segment_sampled - 4.0 / kSamples);
  }
  // Parallel and degenerate segments.
  EXPECT_NEAR(segment_segment_distance({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {2, 1, 0}), 1.0, 1e-15);
  EXPECT_NEAR(segment_segment_distance({0, 0, 0}, {0, 0, 0}, {3, 4, 0}, {3, 4, 0}), 5.0, 1e-15);
  // A collapsed triangle: the distance to its nearest edge.
  EXPECT_NEAR(point_triangle_distance({0.2, 0.2, 0.5}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}), std::hypot(0.2, 0.5), 1e-15);
}

// A sheet crumpled into a 3 cm box (its vertices scattered at random).
SelfContactModel crumpled_sheet(MatrixX3d& x, int n, std::mt19937& rng) {
  const Garment g = grid_garment({flat_panel("sheet", n, n, 0.1, 0.1, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY())}, 1e-9);
  x = g.V;
  std::uniform_real_distribution<double> u(0.0, 0.03);
  for (int v = 0; v < x.rows(); ++v) x.row(v) << u(rng), u(rng), u(rng);
  Scene scene;
  scene.physics.body_contact = false;
  scene.physics.self_contact = true;
  scene.material = *material_preset("cotton-thin");
  return *cloth_model(g, scene, nullptr, {}).self_contact;
}

TEST(SelfContact, BroadPhaseFindsExactlyTheBruteForcePairs) {
  std::mt19937 rng(2);
  MatrixX3d x;
  const SelfContactModel model = crumpled_sheet(x, 12, rng);
  for (const double radius : {0.002, 0.01, 0.03}) {
    std::vector<std::array<int, 2>> brute;
    for (int v : model.vertices)
      for (size_t t = 0; t < model.triangles.size(); ++t) {
        const auto& tri = model.triangles[t];
        if (tri[0] == v || tri[1] == v || tri[2] == v) continue;
        if (point_triangle_distance(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2])) < radius)
          brute.push_back({v, static_cast<int>(t)});
      }
    EXPECT_EQ(self_contact_pairs(model, x, radius), brute) << "radius " << radius;
    EXPECT_FALSE(brute.empty());
    std::vector<std::array<int, 2>> brute_edges;
    for (size_t e = 0; e < model.edges.size(); ++e)
      for (size_t f = e + 1; f < model.edges.size(); ++f) {
        const auto &a = model.edges[e], &b = model.edges[f];
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
        if (segment_segment_distance(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1])) < radius)
          brute_edges.push_back({static_cast<int>(e), static_cast<int>(f)});
      }
    EXPECT_EQ(self_contact_edge_pairs(model, x, radius), brute_edges) << "radius " << radius;
    EXPECT_FALSE(brute_edges.empty());
  }
}

// A vertex over a flat sheet is pushed by one triangle, even above a shared edge or corner;
// between two sheets it is pushed by both.
TEST(SelfContact, OneActingPairPerLayer) {
  Garment g = grid_garment({flat_panel("lower", 4, 4, 0.04, 0.04, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY()),
                            flat_panel("upper", 4, 4, 0.04, 0.04, {0, 0, 0.0013}, Vector3d::UnitX(), Vector3d::UnitY()),
                            flat_panel("dot", 1, 1, 0.001, 0.001, {0.02, 0.02, 0.0005}, Vector3d::UnitX(), Vector3d::UnitY())},
                           1e-9);
  Scene scene;
  scene.physics.body_contact = false;
  scene.physics.self_contact = true;
  scene.material = *material_preset("cotton-thin");
  const ClothModel model = cloth_model(g, scene, nullptr, {});
  // The dot's first corner sits above a grid node of the lower sheet (six triangles meet there)
  // and 0.8 mm below the upper sheet's node.
  const int dot = 50;
  ASSERT_NEAR(g.V(dot, 2), 0.0005, 1e-15);
  int acting = 0;
  for (const auto& [v, t] : self_contact_active_pairs(*model.self_contact, g.V)) acting += v == dot ? 1 : 0;
  EXPECT_EQ(acting, 2);
  EXPECT_EQ(self_contact_pairs(*model.self_contact, g.V, 0.001).size() > 2, true);
}

TEST(SelfContact, StepBoundStopsTunnelling) {
  Garment g = grid_garment({flat_panel("a", 1, 1, 0.01, 0.01, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY()),
                            flat_panel("b", 1, 1, 0.01, 0.01, {0.002, 0.003, 0.005}, Vector3d::UnitX(), Vector3d::UnitY())},
                           1e-9);
  Scene scene;
  scene.physics.body_contact = false;
  scene.physics.self_contact = true;
  scene.material = *material_preset("cotton-thin");
  const SelfContactModel model = *cloth_model(g, scene, nullptr, {}).self_contact;
  // Sheet b drops 20 mm straight through sheet a, 5 mm below it.
  MatrixX3d dx = MatrixX3d::Zero(g.V.rows(), 3);
  for (int v = 4; v < 8; ++v) dx(v, 2) = -0.02;
  const double alpha = self_contact_step_bound(model, g.V, dx, 0.1);
  EXPECT_NEAR(alpha, 0.9 * 0.005 / 0.02, 1e-12);
  // Random steps of random sheets: along the bounded step, no vertex-triangle or edge-edge
  // distance ever falls below a tenth of where it started.
  std::mt19937 rng(4);
  std::normal_distribution<double> move(0.0, 0.01);
  MatrixX3d x;
  const SelfContactModel sheet = crumpled_sheet(x, 6, rng);
  int bounded = 0;
  for (int trial = 0; trial < 20; ++trial) {
    dx.resize(x.rows(), 3);
    for (int v = 0; v < x.rows(); ++v) dx.row(v) << move(rng), move(rng), move(rng);
    const double bound = self_contact_step_bound(sheet, x, dx, 0.1);
    bounded += bound < 1.0 ? 1 : 0;
    for (const double s : {0.25, 0.5, 0.75, 1.0}) {
      const MatrixX3d y = x + s * bound * dx;
      for (int v : sheet.vertices)
        for (const auto& tri : sheet.triangles) {
          if (tri[0] == v || tri[1] == v || tri[2] == v) continue;
          const double before = point_triangle_distance(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2]));
          const double after = point_triangle_distance(y.row(v), y.row(tri[0]), y.row(tri[1]), y.row(tri[2]));
          ASSERT_GE(after, 0.1 * before - 1e-15);
        }
      for (size_t e = 0; e < sheet.edges.size(); ++e)
        for (size_t f = e + 1; f < sheet.edges.size(); ++f) {
          const auto &a = sheet.edges[e], &b = sheet.edges[f];
          if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
          const double before = segment_segment_distance(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1]));
          const double after = segment_segment_distance(y.row(a[0]), y.row(a[1]), y.row(b[0]), y.row(b[1]));
          ASSERT_GE(after, 0.1 * before - 1e-15);
        }
    }
  }
  EXPECT_GT(bounded, 10);  // the bound was active, not always 1
}

// Vertices stitched together (here two panels side by side, sewn by stitches instead of
// welded) and their triangles are not pushed apart; only the chosen region takes part.
TEST(SelfContact, SeamsAndRegions) {
  Garment g = grid_garment({flat_panel("a", 2, 2, 0.02, 0.02, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY()),
                            flat_panel("b", 2, 2, 0.02, 0.02, {0.02 + 1e-9, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY())},
                           1e-12);
  ASSERT_EQ(g.V.rows(), 18);  // not welded
  for (int j = 0; j < 3; ++j) {
    ASSERT_LT((g.V.row(3 * j + 2) - g.V.row(9 + 3 * j)).norm(), 2e-9);
    g.stitches.push_back({{3 * j + 2, -1, 0.0}, {9 + 3 * j, -1, 0.0}});
  }
  Scene scene;
  scene.physics.body_contact = false;
  scene.physics.self_contact = true;
  scene.material = *material_preset("cotton-thin");
  const ClothModel all = cloth_model(g, scene, nullptr, {});
  EXPECT_TRUE(self_contact_pairs(*all.self_contact, g.V, 1e-4).empty());
  EXPECT_EQ(all.self_contact->vertices.size(), 18u);
  g.stitches.clear();  // without the stitches, the seam's vertices touch the other panel
  EXPECT_EQ(self_contact_pairs(*cloth_model(g, scene, nullptr, {}).self_contact, g.V, 1e-4).size(), 12u);
  ClothParams region;
  region.self_contact_vertices = {0, 1, 3, 4};
  const ClothModel part = cloth_model(g, scene, nullptr, {}, region);
  EXPECT_EQ(part.self_contact->vertices.size(), 4u);
  EXPECT_EQ(part.self_contact->triangles.size(), 2u);
  region.self_contact_vertices = {99};
  EXPECT_THROW(cloth_model(g, scene, nullptr, {}, region), ArgumentError);

  // The same region named in the scene: a box around the first panel's lower-left cell, and a
  // listed vertex; a box that holds no vertex adds none.
  VertexSelector box, listed, empty;
  box.box = Eigen::AlignedBox3d(Vector3d(-0.001, -0.001, -1), Vector3d(0.011, 0.001, 1));  // vertices 0, 1
  listed.vertices = {3, 4};
  empty.box = Eigen::AlignedBox3d(Vector3d(5, 5, 5), Vector3d(6, 6, 6));
  scene.self_contact_regions = {box, listed, empty};
  EXPECT_EQ(self_contact_region(scene, g.V), (std::vector<int>{0, 1, 3, 4}));
  const ClothModel named = cloth_model(g, scene, nullptr, {});
  EXPECT_EQ(named.self_contact->vertices, part.self_contact->vertices);
  EXPECT_EQ(named.self_contact->triangles, part.self_contact->triangles);
  listed.vertices = {99};
  scene.self_contact_regions = {listed};
  try {
    cloth_model(g, scene, nullptr, {});
    ADD_FAILURE() << "no error for a region naming a missing vertex";
  } catch (const ArgumentError& e) {
    EXPECT_STREQ(e.what(), "a self-contact region names drape vertex 100 but the garment has 18");
  }
}

} // namespace
} // namespace foldsketch
