// A supernodal Cholesky factorisation in single precision, on the symbolic analysis CHOLMOD
// made (its supernodes, their row sets and the fill-reducing order). Debian's CHOLMOD 3 has no
// single-precision numeric factorisation; single-precision BLAS runs twice as fast as double on
// this machine's cores (dense Cholesky, OpenBLAS, one core: 85 against 41 Gflop/s at n = 1000),
// and the Newton systems need only a step, which the solver refines in double precision
// (SparseCholesky).
//
// Left-looking, as CHOLMOD's own (Ng and Peyton 1993): supernode s gathers A's columns, takes
// the updates of every earlier supernode whose rows reach its columns (one SYRK/GEMM each, or
// our own loop for a small one, scattered into s's rows), then factorises its diagonal block
// (POTRF) and solves its off-diagonal rows (TRSM), or for a narrow supernode both at once in
// our own loop. Which updates there are, in which order, and where each of A's values and each
// update's rows go depends on the pattern alone: the first factorisation of a pattern plans
// that once (SupernodalWorkspace), the later ones follow the plan.
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
  // Supernode s's column and row counts and its rows (its own columns' first).
  int column_count(int s) const { return super[s + 1] - super[s]; }
  int row_count(int s) const { return row_start[s + 1] - row_start[s]; }
  const int* rows_of(int s) const { return rows + row_start[s]; }
};

// One supernode's update of a later one: rows first .. of supernode `source` (its rows that
// fall in the target's columns first: `inside` of them, `below` in all) times their own
// transpose, subtracted from the target's rows relative[at .. at+below-1].
struct SupernodalUpdate {
  int source = 0, first = 0, inside = 0, below = 0;
  long at = 0;
};

// The factorisation's plan, made at the first factorisation of a pattern and kept for the
// later ones (everything in it follows from the pattern alone): where each of A's values goes
// in L, and every update in the order it is applied. Empty: not made yet.
struct SupernodalWorkspace {
  std::vector<long> target;            // per stored value of A: its offset in L
  std::vector<int> update_start;       // per supernode: its updates, update_start[s] .. [s+1]-1
  std::vector<SupernodalUpdate> updates;
  std::vector<int> relative;           // per update, per row: the row's place in the target's rows
  std::vector<float> product;          // one update's product, the largest one's size
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
