// Undirected edges of a triangle mesh with their incident faces.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/types.h"

namespace foldsketch {

struct MeshEdges {
  MatrixX2i E;                          // #E by 2 vertex indices, E(e,0) < E(e,1)
  MatrixX3i FE;                         // #F by 3: FE(f,k) is the edge from corner k to k+1
  std::vector<std::vector<int>> faces;  // faces[e]: the faces incident on edge e (1 = boundary,
                                        // 2 = interior, 3 or more = non-manifold)
};

// Edges of the triangles F (#F by 3, indices in [0, num_vertices)), numbered in order of
// first appearance when walking faces and their corners.
MeshEdges mesh_edges(const MatrixX3i& F, int num_vertices);

// One 64-bit key for the undirected edge between vertices a and b (either order), for hashing.
inline std::uint64_t undirected_edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

} // namespace foldsketch
