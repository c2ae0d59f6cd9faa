// The single-precision supernodal factorisation (sim/supernodal_single.h), through
// SparseCholesky and BisectedCholesky: it factors what CHOLMOD factors to single precision,
// refuses what is not positive definite, and a refined solve is as accurate as a double one.
#include "sim/supernodal_single.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "lib/sim/grid_system.h"
#include "sim/bisected_cholesky.h"
#include "sim/sparse_cholesky.h"

namespace foldsketch {
namespace {

// Single precision's unit roundoff is 6e-8; solves of these well-conditioned systems (shift 25:
// condition number about 10) agree with double ones to a few hundred of it.
constexpr double kSingleAgreement = 1e-5;

VectorXd smooth_rhs(Eigen::Index n) {
  VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b(i) = std::sin(0.1 * static_cast<double>(i)) + 0.5;
  return b;
}

// The 30 x 20 grid's 1800 unknowns take every path of the factorisation and the solves: 454
// updates by our loops and 167 by SYRK / GEMM, 225 supernodes factorised and solved with by our
// loops and 24 by POTRF / TRSM and TRSV / GEMV (counted once, instrumented).
TEST(SupernodalSingle, FactorsWhatCholmodFactorsToSinglePrecision) {
  const Eigen::SparseMatrix<double> A = grid_system(30, 20, 25.0, 11);
  const VectorXd b = smooth_rhs(A.rows());
  SparseCholesky exact;
  SparseCholesky single(FactorPrecision::Single);
  ASSERT_TRUE(exact.factorize(A));
  ASSERT_TRUE(single.factorize(A));
  const VectorXd x = exact.solve(b);
  EXPECT_LT((single.solve(b) - x).norm(), kSingleAgreement * x.norm());
  // The triangular halves and the factor itself, in the factor's order.
  EXPECT_LT((single.solve_lower(b) - exact.solve_lower(b)).norm(), kSingleAgreement * exact.solve_lower(b).norm());
  EXPECT_LT((single.solve_upper(b) - exact.solve_upper(b)).norm(), kSingleAgreement * exact.solve_upper(b).norm());
  const Eigen::MatrixXd block = exact.trailing_block(40);
  EXPECT_LT((single.trailing_block(40) - block).norm(), kSingleAgreement * block.norm());
}

TEST(SupernodalSingle, RefusesWhatIsNotPositiveDefiniteThenTakesNewValues) {
  const Eigen::SparseMatrix<double> A = grid_system(20, 15, 25.0, 12);
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues()(0);
  SparseCholesky single(FactorPrecision::Single);
  single.analyze(A);
  for (const double shift : {-lowest + 1e-2, -lowest - 1e-2, -lowest - 20.0}) {
    Eigen::SparseMatrix<double> B = A;
    for (int k = 0; k < B.rows(); ++k) B.coeffRef(k, k) += shift;
    EXPECT_EQ(single.factorize(B), shift > -lowest) << "shift " << shift;
  }
  ASSERT_TRUE(single.factorize(A));
  const VectorXd b = smooth_rhs(A.rows());
  EXPECT_LT((A * single.solve(b) - b).norm(), kSingleAgreement * b.norm());
}

// BisectedCholesky in single precision: each refinement against the double-precision matrix
// multiplies the error by about cond(A) times single precision's roundoff.
TEST(SupernodalSingle, RefinedSolvesReachDoublePrecision) {
  const Eigen::SparseMatrix<double> A = grid_system(40, 30, 25.0, 13);
  const VectorXd b = smooth_rhs(A.rows());
  const auto residual = [&](int refinements, int min_unknowns) {
    BisectedSettings settings;
    settings.min_unknowns = min_unknowns;
    settings.precision = FactorPrecision::Single;
    settings.refinements = refinements;
    BisectedCholesky cholesky(settings);
    EXPECT_TRUE(cholesky.factorize(A));
    EXPECT_EQ(cholesky.split(), min_unknowns == 1);
    return (A * cholesky.solve(b) - b).norm() / b.norm();
  };
  for (const int min_unknowns : {1, 1 << 30}) {  // split in two halves, and whole
    const double once = residual(0, min_unknowns), refined = residual(1, min_unknowns), twice = residual(2, min_unknowns);
    EXPECT_GT(once, 1e-9) << "an unrefined single-precision solve";
    EXPECT_LT(once, kSingleAgreement);
    EXPECT_LT(refined, 1e-10);
    EXPECT_LT(twice, 1e-13);
  }
}

// Near singular (condition number about 1e5): the single-precision factor still exists and
// two refinements bring the solve to the double-precision one's accuracy.
TEST(SupernodalSingle, RefinementRecoversAnIllConditionedSystem) {
  Eigen::SparseMatrix<double> A = grid_system(20, 15, 25.0, 14);
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues()(0);
  for (int k = 0; k < A.rows(); ++k) A.coeffRef(k, k) += 1e-3 - lowest;
  const VectorXd b = smooth_rhs(A.rows());
  SparseCholesky exact;
  ASSERT_TRUE(exact.factorize(A));
  const VectorXd x = exact.solve(b);
  BisectedSettings settings;
  settings.min_unknowns = 1;
  settings.precision = FactorPrecision::Single;
  settings.refinements = 2;
  BisectedCholesky single(settings);
  ASSERT_TRUE(single.factorize(A));
  EXPECT_LT((single.solve(b) - x).norm(), 1e-8 * x.norm());
  // Switched to double precision, the same object solves as CHOLMOD does.
  single.set_precision(FactorPrecision::Double);
  ASSERT_TRUE(single.factorize(A));
  EXPECT_LT((single.solve(b) - x).norm(), 1e-10 * x.norm());
}

} // namespace
} // namespace foldsketch
