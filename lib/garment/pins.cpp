#include "garment/pins.h"

#include <algorithm>

#include "core/error.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {

std::vector<int> vertices_in_box(const MatrixX3d& V, const Eigen::AlignedBox3d& box) {
  std::vector<int> inside;
  for (int v = 0; v < V.rows(); ++v)
    if (box.contains(V.row(v).transpose())) inside.push_back(v);
  return inside;
}

std::vector<Pin> pins_at(const MatrixX3d& V, std::vector<int> vertices) {
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::vector<Pin> pins;
  for (int v : vertices) {
    if (v < 0 || v >= V.rows()) throw ArgumentError("pins_at: vertex index outside V");
    pins.push_back({v, V.row(v).transpose()});
  }
  return pins;
}

PinnedEdge most_stretched_pinned_edge(const Garment& g, const std::vector<int>& pinned) {
  std::vector<char> held(static_cast<size_t>(g.V.rows()), 0);
  for (int v : pinned)
    if (v >= 0 && v < g.V.rows()) held[static_cast<size_t>(v)] = 1;
  const MatrixX3d drape = edge_lengths(g.V, g.F), pattern = edge_lengths(g.P, g.FP);  // column k: opposite corner k
  PinnedEdge most;
  for (Eigen::Index f = 0; f < g.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = g.F(f, (k + 1) % 3), b = g.F(f, (k + 2) % 3);
      if (!held[static_cast<size_t>(a)] || !held[static_cast<size_t>(b)] || !(pattern(f, k) > 0)) continue;
      const double stretch = drape(f, k) / pattern(f, k);
      if (most.v0 < 0 || stretch > most.stretch) most = {a, b, stretch};
    }
  return most;
}

} // namespace foldsketch
