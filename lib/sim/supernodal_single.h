// A supernodal Cholesky factorisation in single precision, on the symbolic analysis CHOLMOD
// made (its supernodes, their row sets and the fill-reducing order). Debian's CHOLMOD 3 has no
// single-precision numeric factorisation; single-precision BLAS runs twice as fast as double on
// this machine's cores (dense Cholesky, OpenBLAS, one core: 85 against 41 Gflop/s at n = 1000),
// and the Newton systems need only a step, which the solver refines in double precision
// (SparseCholesky).
//
// Left-looking, as CHOLMOD's own (Ng and Peyton 1993): supernode s gathers A's columns, takes
// the updates of every earlier supernode whose rows reach its columns (one SYRK/GEMM each,
// scattered through a row map), then factorises its diagonal block (POTRF) and solves its
// off-diagonal rows (TRSM).
#pragma once

#include <vector>

namespace foldsketch {

// The supernodal pattern, as cholmod_factor holds it after a supernodal analysis: supernode k
// holds columns super[k] .. super[k+1]-1, its rows are rows[row_start[k] .. row_start[k+1]-1]
// (its own columns first), and its values a dense column-major block from value_start[k].
struct SupernodalPattern {
  int n = 0;
  int supernodes = 0;
  const int* super = nullptr;
  const int* row_start = nullptr;
  const int* value_start = nullptr;
  const int* rows = nullptr;
  long values = 0;
};

// Workspace kept between factorisations of one pattern.
struct SupernodalWorkspace {
  std::vector<int> row_map, column_supernode, head, next, position;
  std::vector<float> update;
};

// Factorises the lower triangle of P A P^T (compressed columns, rows sorted, each column's
// rows >= its index) into L (pattern.values floats). False when a pivot is not positive (the
// matrix is not positive definite in single precision).
bool factorize_single(const SupernodalPattern& pattern, const int* column_start, const int* row_index,
                      const double* value, std::vector<float>& L, SupernodalWorkspace& work);

// In place, in the factor's order: x = L^-1 x and x = L^-T x (single precision).
void solve_lower_single(const SupernodalPattern& pattern, const std::vector<float>& L, float* x);
void solve_upper_single(const SupernodalPattern& pattern, const std::vector<float>& L, float* x);

} // namespace foldsketch
