// BisectedCholesky: the two halves and the separator's Schur complement solve what one
// factorisation solves, refuse what it refuses, and a small system is left whole.
#include "sim/bisected_cholesky.h"

#include <random>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "sim/sparse_cholesky.h"
#include "lib/sim/grid_system.h"

namespace foldsketch {
namespace {

BisectedSettings always_split() {
  BisectedSettings s;
  s.min_unknowns = 1;
  return s;
}

TEST(BisectedCholesky, SolvesWhatOneFactorisationSolves) {
  const Eigen::SparseMatrix<double> A = grid_system(30, 20, 25.0, 1);
  VectorXd b(A.rows());
  for (int i = 0; i < b.size(); ++i) b(i) = std::sin(0.1 * i);
  SparseCholesky whole;
  ASSERT_TRUE(whole.factorize(A));
  const VectorXd expected = whole.solve(b);
  BisectedCholesky split(always_split());
  split.analyze(A);
  ASSERT_TRUE(split.split());
  EXPECT_GT(split.separator_size(), 0);
  EXPECT_LT(split.separator_size(), A.rows() / 5);
  ASSERT_TRUE(split.factorize(A));
  const VectorXd x = split.solve(b);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  // Lower storage reads the same.
  const Eigen::SparseMatrix<double> lower = A.triangularView<Eigen::Lower>();
  BisectedCholesky from_lower(always_split());
  ASSERT_TRUE(from_lower.factorize(lower));
  EXPECT_LT((from_lower.solve(b) - expected).norm(), 1e-10 * expected.norm());
}

TEST(BisectedCholesky, RefusesWhatIsNotPositiveDefiniteThenTakesNewValues) {
  const Eigen::SparseMatrix<double> A = grid_system(20, 15, 25.0, 2);
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues()(0);
  BisectedCholesky split(always_split());
  split.analyze(A);
  ASSERT_TRUE(split.split());
  // Shifted just above and just below definiteness: the halves (principal submatrices, their
  // eigenvalues above A's) stay definite, so the refusal must come from the Schur complement;
  // and shifted far below, a half refuses.
  for (const double shift : {-lowest + 1e-3, -lowest - 1e-3, -lowest - 20.0}) {
    Eigen::SparseMatrix<double> B = A;
    for (int k = 0; k < B.rows(); ++k) B.coeffRef(k, k) += shift;
    EXPECT_EQ(split.factorize(B), shift > -lowest) << "shift " << shift;
    EXPECT_EQ(split.factorized(), shift > -lowest);
  }
  // New values after a refusal: the factor is theirs.
  ASSERT_TRUE(split.factorize(A));
  const VectorXd b = VectorXd::Ones(A.rows());
  const VectorXd x = split.solve(b);
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  EXPECT_EQ(split.factorizations(), 4);
}

TEST(BisectedCholesky, LeavesASmallSystemWhole) {
  const Eigen::SparseMatrix<double> A = grid_system(6, 5, 25.0, 3);
  BisectedCholesky small;  // default threshold
  ASSERT_TRUE(small.factorize(A));
  EXPECT_FALSE(small.split());
  const VectorXd b = VectorXd::Ones(A.rows());
  EXPECT_LT((A * small.solve(b) - b).norm(), 1e-10 * b.norm());
}

// analysed_for tells a caller handed an analysed factorisation whether it fits its matrix: the
// same pattern with other values does, another pattern (one more coupling) does not.
TEST(BisectedCholesky, KnowsWhichPatternItAnalysed) {
  const Eigen::SparseMatrix<double> A = grid_system(20, 15, 25.0, 4);
  BisectedCholesky split(always_split());
  EXPECT_FALSE(split.analysed_for(A));
  split.analyze(A);
  EXPECT_TRUE(split.analysed_for(A));
  Eigen::SparseMatrix<double> scaled = 2.0 * A;
  scaled.makeCompressed();
  EXPECT_TRUE(split.analysed_for(scaled));
  Eigen::SparseMatrix<double> coupled = A;
  const int far = static_cast<int>(A.rows()) - 1;
  coupled.coeffRef(far, 0) += 1e-3;
  coupled.coeffRef(0, far) += 1e-3;
  coupled.makeCompressed();
  ASSERT_NE(coupled.nonZeros(), A.nonZeros());
  EXPECT_FALSE(split.analysed_for(coupled));
  split.analyze(coupled);
  EXPECT_TRUE(split.analysed_for(coupled));
  EXPECT_FALSE(split.analysed_for(A));
}

} // namespace
} // namespace foldsketch
