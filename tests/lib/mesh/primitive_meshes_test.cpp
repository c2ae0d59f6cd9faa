#include "mesh/primitive_meshes.h"

#include <numbers>

#include <gtest/gtest.h>

#include "mesh/boundary_loops.h"
#include "mesh/mesh_edges.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(PrimitiveMeshes, BoxIsClosedAndFacesOutwards) {
  const TriangleMesh m = box_mesh({-1, 0, -2}, {1, 3, 2});
  EXPECT_TRUE(boundary_loops(m.F, 8).empty());
  EXPECT_NEAR(test::enclosed_volume(m.V, m.F), 2 * 3 * 4, 1e-12);
}

TEST(PrimitiveMeshes, CylinderIsClosedAndFacesOutwards) {
  const int n = 64;
  const TriangleMesh m = cylinder_mesh({0.5, -0.5}, 0.1, 0.0, 2.0, n);
  EXPECT_TRUE(boundary_loops(m.F, static_cast<int>(m.V.rows())).empty());
  const double polygon_area = 0.5 * n * 0.01 * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(test::enclosed_volume(m.V, m.F), polygon_area * 2.0, 1e-12);
}

} // namespace
} // namespace foldsketch
