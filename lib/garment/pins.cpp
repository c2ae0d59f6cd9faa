#include "garment/pins.h"

#include <algorithm>

#include "core/error.h"

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
  PinnedEdge most;
  for (Eigen::Index f = 0; f < g.F.rows(); ++f)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, a = g.F(f, i), b = g.F(f, j);
      if (!held[static_cast<size_t>(a)] || !held[static_cast<size_t>(b)]) continue;
      const double pattern = (g.P.row(g.FP(f, i)) - g.P.row(g.FP(f, j))).norm();
      const double stretch = (g.V.row(a) - g.V.row(b)).norm() / pattern;
      if (pattern > 0 && (most.v0 < 0 || stretch > most.stretch)) most = {a, b, stretch};
    }
  return most;
}

} // namespace foldsketch
