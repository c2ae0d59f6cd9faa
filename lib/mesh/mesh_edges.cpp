#include "mesh/mesh_edges.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>

#include "core/error.h"

namespace foldsketch {

MeshEdges mesh_edges(const MatrixX3i& F, int num_vertices) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= num_vertices))
    throw ArgumentError("mesh_edges: face index outside [0, num_vertices)");
  MeshEdges out;
  out.FE.resize(F.rows(), 3);
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(static_cast<size_t>(F.rows()) * 2);
  std::vector<std::array<int, 2>> edges;
  for (int f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      int a = F(f, k), b = F(f, (k + 1) % 3);
      if (a > b) std::swap(a, b);
      const std::uint64_t key = undirected_edge_key(a, b);
      auto [it, inserted] = index.try_emplace(key, static_cast<int>(edges.size()));
      if (inserted) {
        edges.push_back({a, b});
        out.faces.emplace_back();
      }
      out.FE(f, k) = it->second;
      out.faces[it->second].push_back(f);
    }
  }
  out.E.resize(static_cast<Eigen::Index>(edges.size()), 2);
  for (size_t e = 0; e < edges.size(); ++e) out.E.row(static_cast<Eigen::Index>(e)) << edges[e][0], edges[e][1];
  return out;
}

} // namespace foldsketch
