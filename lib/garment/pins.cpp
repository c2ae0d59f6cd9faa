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

} // namespace foldsketch
