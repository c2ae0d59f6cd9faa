#include "mesh/boundary_loops.h"

#include <algorithm>

#include "mesh/mesh_edges.h"

namespace foldsketch {

std::vector<std::vector<int>> boundary_loops(const MatrixX3i& F, int num_vertices) {
  const MeshEdges edges = mesh_edges(F, num_vertices);
  // Outgoing boundary half-edges per vertex, in face order.
  std::vector<std::vector<int>> next(static_cast<size_t>(num_vertices));
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (edges.faces[edges.FE(f, k)].size() == 1) next[F(f, k)].push_back(F(f, (k + 1) % 3));

  std::vector<std::vector<int>> loops;
  for (int start = 0; start < num_vertices; ++start) {
    while (!next[start].empty()) {
      std::vector<int> loop{start};
      int v = start;
      while (true) {
        const int w = next[v].front();
        next[v].erase(next[v].begin());
        if (w == start) break;
        loop.push_back(w);
        v = w;
        if (next[v].empty()) break;  // open chain: only possible on inconsistent orientation
      }
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

} // namespace foldsketch
