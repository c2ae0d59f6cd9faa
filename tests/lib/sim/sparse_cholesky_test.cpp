// SparseCholesky: factorises the lower triangle of a symmetric matrix through its own permuted
// copy; checked against dense solves of random sparse systems.
#include "sim/sparse_cholesky.h"

#include <random>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace foldsketch {
namespace {

// A random symmetric matrix with the sparsity of a path graph plus random long-range links,
// shifted on the diagonal by `shift` (positive definite for a large shift). Full storage.
Eigen::SparseMatrix<double> random_symmetric(int n, double shift, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> index(0, n - 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, shift + value(rng));
  const auto link = [&](int i, int j) {
    const double v = value(rng);
    t.emplace_back(i, j, v);
    t.emplace_back(j, i, v);
  };
  for (int i = 0; i + 1 < n; ++i) link(i, i + 1);
  for (int k = 0; k < 2 * n; ++k) {
    const int i = index(rng), j = index(rng);
    if (i != j) link(i, j);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

Eigen::SparseMatrix<double> lower_of(const Eigen::SparseMatrix<double>& A) {
  Eigen::SparseMatrix<double> L = A.triangularView<Eigen::Lower>();
  L.makeCompressed();
  return L;
}

TEST(SparseCholesky, SolvesFullAndLowerStoredSystems) {
  const int n = 300;
  const Eigen::SparseMatrix<double> A = random_symmetric(n, 8.0, 1);
  const VectorXd b = VectorXd::LinSpaced(n, -1.0, 2.0);
  const VectorXd expected = Eigen::MatrixXd(A).ldlt().solve(b);
  for (const Eigen::SparseMatrix<double>& stored : {A, lower_of(A)}) {
    SparseCholesky cholesky;
    cholesky.analyze(stored);
    ASSERT_TRUE(cholesky.factorize(stored));
    EXPECT_LT((cholesky.solve(b) - expected).norm(), 1e-10 * expected.norm());
  }
}

TEST(SparseCholesky, RefusesAnIndefiniteMatrixThenFactorisesNewValuesOfTheSamePattern) {
  const int n = 200;
  Eigen::SparseMatrix<double> A = lower_of(random_symmetric(n, 8.0, 2));
  SparseCholesky cholesky;
  cholesky.analyze(A);
  ASSERT_TRUE(cholesky.factorize(A));
  // Same pattern, one diagonal entry negative: not positive definite.
  Eigen::SparseMatrix<double> B = A;
  B.coeffRef(n / 2, n / 2) = -1.0;
  EXPECT_FALSE(cholesky.factorize(B));
  EXPECT_FALSE(cholesky.factorized());
  // New values, same pattern: the factor is the new matrix's, not a stale one.
  Eigen::SparseMatrix<double> C = A;
  for (int k = 0; k < n; ++k) C.coeffRef(k, k) += 5.0;
  ASSERT_TRUE(cholesky.factorize(C));
  const VectorXd b = VectorXd::Ones(n);
  const Eigen::MatrixXd full = Eigen::MatrixXd(C).selfadjointView<Eigen::Lower>();
  const VectorXd expected = full.ldlt().solve(b);
  EXPECT_LT((cholesky.solve(b) - expected).norm(), 1e-10 * expected.norm());
  EXPECT_EQ(cholesky.factorizations(), 3);
}

TEST(SparseCholesky, RejectsAMatrixWithAnotherPattern) {
  const Eigen::SparseMatrix<double> A = lower_of(random_symmetric(50, 8.0, 3));
  const Eigen::SparseMatrix<double> other = lower_of(random_symmetric(50, 8.0, 4));
  SparseCholesky cholesky;
  cholesky.analyze(A);
  if (other.nonZeros() == A.nonZeros()) GTEST_SKIP() << "the two random patterns have the same size";
  EXPECT_THROW(cholesky.factorize(other), std::exception);
}

} // namespace
} // namespace foldsketch
