// BisectedCholesky: the two halves and the separator's Schur complement solve what one
// factorisation solves, refuse what it refuses, and a small system is left whole; a
// single-precision factor's solve that its refinement leaves inaccurate is rescued by
// conjugate gradients, or found indefinite.
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

// Nearly singular (smallest eigenvalue 3e-7 against a largest of about 10): one refinement of
// the single-precision solve leaves a relative residual above kSingleSolveResidual, and the
// conjugate-gradient rescue brings it under kRescuedSolveResidual in a few iterations.
TEST(BisectedCholesky, RescuesAnIllConditionedSinglePrecisionSolve) {
  Eigen::SparseMatrix<double> A = grid_system(20, 15, 25.0, 5);
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues()(0);
  for (int k = 0; k < A.rows(); ++k) A.coeffRef(k, k) += -lowest + 3e-7;
  VectorXd b(A.rows());
  for (int i = 0; i < b.size(); ++i) b(i) = std::sin(0.1 * i);
  BisectedSettings settings = always_split();
  settings.precision = FactorPrecision::Single;
  settings.rescue_iterations = 0;
  BisectedCholesky refined_only(settings);
  ASSERT_TRUE(refined_only.factorize(A));
  refined_only.solve(b);
  EXPECT_GT(refined_only.last_relative_residual(), kSingleSolveResidual);
  EXPECT_FALSE(refined_only.last_solve_trusted());
  EXPECT_FALSE(refined_only.last_solve_indefinite());

  settings.rescue_iterations = 30;
  BisectedCholesky rescued(settings);
  ASSERT_TRUE(rescued.factorize(A));
  const VectorXd x = rescued.solve(b);
  EXPECT_TRUE(rescued.last_solve_trusted());
  EXPECT_FALSE(rescued.last_solve_indefinite());
  EXPECT_LE(rescued.last_relative_residual(), 10 * kRescuedSolveResidual);
  EXPECT_LT((A * x - b).norm(), 10 * kRescuedSolveResidual * b.norm());
  EXPECT_GT(rescued.rescue_iterations(), 0);
  EXPECT_LE(rescued.rescue_iterations(), 5);
}

// A stiff matrix (eigenvalues 1e4) with one slightly negative eigenvalue (-1e-5), below single
// precision's rounding of the rest: for some of these random bases the single-precision
// factorisation succeeds, and the solve must then say the matrix is indefinite, which a
// double-precision factorisation confirms by refusing it.
TEST(BisectedCholesky, FindsAnIndefiniteMatrixThatSinglePrecisionPassed) {
  const int n = 60;
  int passed = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    Eigen::MatrixXd R(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) R(i, j) = value(rng);
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(R).householderQ();
    VectorXd eigenvalues = VectorXd::Constant(n, 1e4);
    eigenvalues(0) = -1e-5;
    Eigen::MatrixXd dense = Q * eigenvalues.asDiagonal() * Q.transpose();
    dense = (0.5 * (dense + dense.transpose())).eval();
    const Eigen::SparseMatrix<double> A = dense.sparseView();
    BisectedSettings settings;
    settings.precision = FactorPrecision::Single;
    BisectedCholesky single(settings);
    if (!single.factorize(A)) continue;
    ++passed;
    single.solve(VectorXd::Ones(n));
    EXPECT_FALSE(single.last_solve_trusted()) << "seed " << seed;
    EXPECT_TRUE(single.last_solve_indefinite()) << "seed " << seed;
    BisectedCholesky exact;
    EXPECT_FALSE(exact.factorize(A)) << "seed " << seed;
  }
  EXPECT_GT(passed, 0) << "no basis let single precision pass the indefinite matrix";
}

} // namespace
} // namespace foldsketch
