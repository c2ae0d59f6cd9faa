#include "mesh/connected_components.h"

#include <numeric>
#include <vector>

#include "core/error.h"

namespace foldsketch {
namespace {
int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}
} // namespace

VectorXi face_components(const MatrixX3i& F, int num_vertices) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= num_vertices))
    throw ArgumentError("face_components: face index outside [0, num_vertices)");
  std::vector<int> parent(static_cast<size_t>(num_vertices));
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 1; k < 3; ++k) {
      const int a = find_root(parent, F(f, 0)), b = find_root(parent, F(f, k));
      if (a != b) parent[b] = a;
    }
  std::vector<int> id(static_cast<size_t>(num_vertices), -1);
  VectorXi C(F.rows());
  int count = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const int root = find_root(parent, F(f, 0));
    if (id[root] < 0) id[root] = count++;
    C(f) = id[root];
  }
  return C;
}

} // namespace foldsketch
