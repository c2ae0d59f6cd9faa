// Sparse Cholesky factorisation of the Newton systems through CHOLMOD (supernodal, METIS
// ordering): the symbolic analysis is done once per sparsity pattern and reused for every
// numeric factorisation.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "core/types.h"

namespace foldsketch {

// Makes CHOLMOD's OpenMP regions and OpenBLAS run on the calling thread (see the .cpp); every
// thread that factorises calls it (OpenMP's setting is per thread).
void keep_factorisation_on_this_thread();

// The numeric factorisation's arithmetic. Single: this project's own supernodal factorisation
// (sim/supernodal_single.h) on CHOLMOD's analysis, about twice as fast; its solves are good to
// single precision, so a caller that needs more refines them (BisectedCholesky does).
enum class FactorPrecision { Double, Single };

class SparseCholesky {
public:
  explicit SparseCholesky(FactorPrecision precision = FactorPrecision::Double);
  // Takes effect at the next factorisation.
  void set_precision(FactorPrecision precision) { precision_ = precision; }
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Symbolic analysis of A's pattern (A symmetric, full or lower storage; the lower triangle
  // is read). Called again only when the pattern changes.
  void analyze(const Eigen::SparseMatrix<double>& A);
  // The same with a given fill-reducing ordering, used as is: row ordering[k] of A is
  // eliminated k-th (BisectedCholesky puts its separator last this way).
  void analyze(const Eigen::SparseMatrix<double>& A, const std::vector<int>& ordering);
  // Numeric factorisation; false when A is not positive definite (nothing usable is kept).
  bool factorize(const Eigen::SparseMatrix<double>& A);
  bool factorized() const;
  VectorXd solve(const VectorXd& b) const;
  // With P A P^T = L L^T, in the factor's order (entry k is row ordering[k] of A): L^-1 b and
  // L^-T b.
  VectorXd solve_lower(const VectorXd& b) const;
  VectorXd solve_upper(const VectorXd& b) const;
  // The last m rows and columns of L, dense, zeros above the diagonal.
  Eigen::MatrixXd trailing_block(int m) const;

  int factorizations() const { return factorizations_; }
  double analyze_seconds() const { return analyze_seconds_; }
  double factorize_seconds() const { return factorize_seconds_; }
  double solve_seconds() const { return solve_seconds_; }

private:
  void analyze_with(const Eigen::SparseMatrix<double>& A, const std::vector<int>* ordering);
  VectorXd solve_single(int system, const VectorXd& b) const;
  VectorXd solve_system(int system, const VectorXd& b) const;
  void build_permuted(const Eigen::SparseMatrix<double>& A);
  struct State;
  std::unique_ptr<State> state_;
  FactorPrecision precision_;
  int factorizations_ = 0;
  double analyze_seconds_ = 0, factorize_seconds_ = 0;
  mutable double solve_seconds_ = 0;
};

} // namespace foldsketch
