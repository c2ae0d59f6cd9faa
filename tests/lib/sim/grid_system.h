// Test matrices for the sparse Cholesky factorisations (bisected_cholesky_test,
// supernodal_single_test).
#pragma once

#include <random>
#include <vector>

#include <Eigen/SparseCore>

namespace foldsketch {

// A cloth-like system: 3 unknowns per vertex of a w x h grid, each vertex coupled to its grid
// neighbours by random symmetric 3x3 blocks, the diagonal shifted by `shift`. Full storage.
inline Eigen::SparseMatrix<double> grid_system(int w, int h, double shift, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  const auto vertex = [&](int i, int j) { return i * h + j; };
  const auto couple = [&](int a, int b) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const double v = value(rng);
        t.emplace_back(3 * a + r, 3 * b + c, v);
        t.emplace_back(3 * b + c, 3 * a + r, v);
      }
  };
  for (int i = 0; i < w; ++i)
    for (int j = 0; j < h; ++j) {
      for (int r = 0; r < 3; ++r) t.emplace_back(3 * vertex(i, j) + r, 3 * vertex(i, j) + r, shift + value(rng));
      if (i + 1 < w) couple(vertex(i, j), vertex(i + 1, j));
      if (j + 1 < h) couple(vertex(i, j), vertex(i, j + 1));
      if (i + 1 < w && j + 1 < h) couple(vertex(i, j), vertex(i + 1, j + 1));
    }
  Eigen::SparseMatrix<double> A(3 * w * h, 3 * w * h);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

} // namespace foldsketch
