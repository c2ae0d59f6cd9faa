// Shared by the CHOLMOD wrappers (SparseCholesky, BisectedCholesky): a no-copy CHOLMOD view of
// an Eigen matrix, and the wall clock their phase timings use.
#pragma once

#include <chrono>

#include <Eigen/SparseCore>
#include <cholmod.h>

namespace foldsketch {

// A CHOLMOD view (no copy) of a compressed Eigen column matrix, read as symmetric lower.
inline cholmod_sparse cholmod_lower_view(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace foldsketch
