// Sparse Cholesky factorisation of the Newton systems through CHOLMOD (supernodal, METIS
// ordering): the symbolic analysis is done once per sparsity pattern and reused for every
// numeric factorisation.
#pragma once

#include <memory>

#include <Eigen/SparseCore>

#include "core/types.h"

namespace foldsketch {

class SparseCholesky {
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Symbolic analysis of A's pattern (A symmetric, full or lower storage; the lower triangle
  // is read). Called again only when the pattern changes.
  void analyze(const Eigen::SparseMatrix<double>& A);
  // Numeric factorisation; false when A is not positive definite (nothing usable is kept).
  bool factorize(const Eigen::SparseMatrix<double>& A);
  bool factorized() const;
  VectorXd solve(const VectorXd& b) const;

  int factorizations() const { return factorizations_; }
  double analyze_seconds() const { return analyze_seconds_; }
  double factorize_seconds() const { return factorize_seconds_; }
  double solve_seconds() const { return solve_seconds_; }

private:
  void build_permuted(const Eigen::SparseMatrix<double>& A);
  struct State;
  std::unique_ptr<State> state_;
  int factorizations_ = 0;
  double analyze_seconds_ = 0, factorize_seconds_ = 0;
  mutable double solve_seconds_ = 0;
};

} // namespace foldsketch
