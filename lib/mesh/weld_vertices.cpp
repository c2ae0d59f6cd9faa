#include "mesh/weld_vertices.h"

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "core/error.h"

namespace foldsketch {

VectorXi weld_vertices(const MatrixX3d& V, double tolerance) {
  if (!(tolerance > 0.0)) throw ArgumentError("weld_vertices: tolerance must be positive");
  // Hash rows into cells of side `tolerance`; a match can only be in the 27 neighbouring cells.
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  VectorXi weld(V.rows());
  std::vector<int> first_row;
  for (int v = 0; v < V.rows(); ++v) {
    std::array<long long, 3> cell;
    for (int d = 0; d < 3; ++d) cell[d] = static_cast<long long>(std::floor(V(v, d) / tolerance));
    int found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it == cells.end()) continue;
          for (int w : it->second)
            if ((V.row(first_row[w]) - V.row(v)).norm() < tolerance) { found = w; break; }
        }
    if (found < 0) {
      found = static_cast<int>(first_row.size());
      first_row.push_back(v);
      cells[cell].push_back(found);
    }
    weld(v) = found;
  }
  return weld;
}

MatrixX3d welded_positions(const MatrixX3d& V, const VectorXi& weld) {
  const int n = weld.size() ? weld.maxCoeff() + 1 : 0;
  MatrixX3d W(n, 3);
  std::vector<bool> set(static_cast<size_t>(n), false);
  for (int v = 0; v < V.rows(); ++v)
    if (!set[weld(v)]) { W.row(weld(v)) = V.row(v); set[weld(v)] = true; }
  return W;
}

} // namespace foldsketch
