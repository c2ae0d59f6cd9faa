#include "mesh/mesh_edges.h"

#include <gtest/gtest.h>

namespace foldsketch {
namespace {

TEST(MeshEdges, TwoTrianglesShareOneInteriorEdge) {
  MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  const MeshEdges e = mesh_edges(F, 4);
  ASSERT_EQ(e.E.rows(), 5);
  int interior = 0;
  for (const auto& faces : e.faces) interior += faces.size() == 2;
  EXPECT_EQ(interior, 1);
  // FE(0,2) is edge 2->0 and FE(1,0) is edge 0->2: the same undirected edge.
  EXPECT_EQ(e.FE(0, 2), e.FE(1, 0));
  for (int i = 0; i < e.E.rows(); ++i) EXPECT_LT(e.E(i, 0), e.E(i, 1));
}

TEST(MeshEdges, ThreeTrianglesOnOneEdgeAreNonManifold) {
  MatrixX3i F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const MeshEdges e = mesh_edges(F, 5);
  EXPECT_EQ(e.faces[e.FE(0, 0)].size(), 3u);
}

TEST(MeshEdges, RejectsIndicesOutOfRange) {
  MatrixX3i F(1, 3);
  F << 0, 1, 5;
  EXPECT_THROW(mesh_edges(F, 3), std::invalid_argument);
}

} // namespace
} // namespace foldsketch
