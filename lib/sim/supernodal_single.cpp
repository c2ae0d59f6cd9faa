#include "sim/supernodal_single.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "sim/blas.h"

namespace foldsketch {
namespace {
const char kLower = 'L', kNo = 'N', kTransposed = 'T', kRight = 'R';
const float kOne = 1.0f, kZero = 0.0f, kMinusOne = -1.0f;
const int kUnitStride = 1;

// Below these sizes our own loops beat a BLAS or LAPACK call, whose fixed cost (argument
// checks, buffer management, a lock that the two halves' threads contend for) is about a
// microsecond. An update of at most kLoopUpdate multiply-adds is computed and scattered in one
// pass; a supernode of at most kLoopColumns columns (half of the 20K skirt's supernodes have 3
// or 4) is factorised, diagonal block and the rows below together, by a plain left-looking
// Cholesky, and its triangular solves are plain loops instead of TRSV and GEMV. On the 20K
// skirt's Newton matrix, as two halves on two cores, against BLAS and LAPACK for all:
// factorisations 0.88 of the time (our choice among 1024-8192 and 8-32; 0.92 with the update
// loops alone, 0.97 with the supernode loop alone), solves 0.70 (0.86-0.88 with 4-8 columns,
// 0.70 with 32). bench/drape_bench.txt, session 41.
constexpr long kLoopUpdate = 2048;
constexpr int kLoopColumns = 16;

// The plan (SupernodalWorkspace): the left-looking order of the updates, found as the numeric
// factorisation once found it, through linked lists of the supernodes that update each next.
void make_plan(const SupernodalPattern& p, const int* column_start, const int* row_index, SupernodalWorkspace& w) {
  const auto n = static_cast<size_t>(p.n), supernodes = static_cast<size_t>(p.supernodes);
  std::vector<int> row_map(n, 0), column_supernode(n, 0), head(supernodes, -1), next(supernodes, -1), position(supernodes, 0);
  size_t largest = 0;
  for (int s = 0; s < p.supernodes; ++s) {
    for (int j = p.super[s]; j < p.super[s + 1]; ++j) column_supernode[static_cast<size_t>(j)] = s;
    const auto rows = static_cast<size_t>(p.row_count(s));
    largest = std::max(largest, rows * rows);
  }
  // Supernode s has had its columns factorised down to row offset `from` of its rows: queue it
  // on the supernode that holds its next row, which it updates next.
  const auto queue = [&](int s, int from) {
    if (from >= p.row_count(s)) return;
    const int target = column_supernode[static_cast<size_t>(p.rows_of(s)[from])];
    position[static_cast<size_t>(s)] = from;
    next[static_cast<size_t>(s)] = head[static_cast<size_t>(target)];
    head[static_cast<size_t>(target)] = s;
  };
  w.target.assign(static_cast<size_t>(column_start[p.n]), -1);
  w.update_start.assign(supernodes + 1, 0);
  w.updates.clear();
  w.relative.clear();
  for (int s = 0; s < p.supernodes; ++s) {
    const int k1 = p.super[s], k2 = p.super[s + 1], rows = p.row_count(s);
    const int* row = p.rows_of(s);
    for (int i = 0; i < rows; ++i) row_map[static_cast<size_t>(row[i])] = i;
    for (int j = k1; j < k2; ++j)
      for (int q = column_start[j]; q < column_start[j + 1]; ++q)
        w.target[static_cast<size_t>(q)] = p.value_start[s] + static_cast<long>(j - k1) * rows + row_map[static_cast<size_t>(row_index[q])];
    w.update_start[static_cast<size_t>(s)] = static_cast<int>(w.updates.size());
    int d = head[static_cast<size_t>(s)];
    while (d >= 0) {
      const int after = next[static_cast<size_t>(d)];
      const int d_rows = p.row_count(d);
      const int* d_row = p.rows_of(d);
      const int p1 = position[static_cast<size_t>(d)];
      int p2 = p1;
      while (p2 < d_rows && d_row[p2] < k2) ++p2;
      w.updates.push_back({d, p1, p2 - p1, d_rows - p1, static_cast<long>(w.relative.size())});
      for (int i = p1; i < d_rows; ++i) w.relative.push_back(row_map[static_cast<size_t>(d_row[i])]);
      queue(d, p2);
      d = after;
    }
    queue(s, k2 - k1);
  }
  w.update_start[supernodes] = static_cast<int>(w.updates.size());
  w.product.assign(largest, 0.0f);
}

// block (rows x columns, column-major, leading dimension rows) = its Cholesky factor: the
// diagonal block's lower triangle and the rows below it times that factor's inverse
// transpose (POTRF and TRSM at once). False at a pivot that is not positive.
bool factor_panel(float* block, int rows, int columns) {
  for (int j = 0; j < columns; ++j) {
    float* column = block + static_cast<ptrdiff_t>(j) * rows;
    for (int k = 0; k < j; ++k) {
      const float* earlier = block + static_cast<ptrdiff_t>(k) * rows;
      const float a = earlier[j];
      for (int i = j; i < rows; ++i) column[i] -= a * earlier[i];
    }
    if (!(column[j] > 0.0f)) return false;
    const float pivot = std::sqrt(column[j]);
    column[j] = pivot;
    const float inverse = 1.0f / pivot;
    for (int i = j + 1; i < rows; ++i) column[i] *= inverse;
  }
  return true;
}
} // namespace

bool factorize_single(const SupernodalPattern& p, const int* column_start, const int* row_index, const double* value,
                      std::vector<float>& L, SupernodalWorkspace& w) {
  if (w.update_start.size() != static_cast<size_t>(p.supernodes) + 1) make_plan(p, column_start, row_index, w);
  L.resize(static_cast<size_t>(p.values));
  for (int s = 0; s < p.supernodes; ++s) {
    const int columns = p.column_count(s), rows = p.row_count(s);
    float* block = L.data() + p.value_start[s];
    // A's columns, into the zeroed block (while it is in cache).
    std::fill(block, block + static_cast<ptrdiff_t>(rows) * columns, 0.0f);
    for (int q = column_start[p.super[s]]; q < column_start[p.super[s + 1]]; ++q)
      L[static_cast<size_t>(w.target[static_cast<size_t>(q)])] = static_cast<float>(value[q]);
    // Updates from every earlier supernode whose rows reach this one's columns.
    for (int u = w.update_start[static_cast<size_t>(s)]; u < w.update_start[static_cast<size_t>(s) + 1]; ++u) {
      const SupernodalUpdate& up = w.updates[static_cast<size_t>(u)];
      const int d = up.source, inside = up.inside, below = up.below;
      const int d_rows = p.row_count(d), d_columns = p.column_count(d);
      const float* Ld = L.data() + p.value_start[d] + up.first;
      const int* to = w.relative.data() + up.at;
      if (static_cast<long>(inside) * below * d_columns <= kLoopUpdate) {
        for (int j = 0; j < inside; ++j) {
          float* column = block + static_cast<ptrdiff_t>(to[j]) * rows;
          for (int k = 0; k < d_columns; ++k) {
            const float* source = Ld + static_cast<ptrdiff_t>(k) * d_rows;
            const float a = source[j];
            for (int i = j; i < below; ++i) column[to[i]] -= a * source[i];
          }
        }
        continue;
      }
      float* C = w.product.data();
      ssyrk_(&kLower, &kNo, &inside, &d_columns, &kOne, Ld, &d_rows, &kZero, C, &below, 1, 1);
      if (below > inside) {
        const int rest = below - inside;
        sgemm_(&kNo, &kTransposed, &rest, &inside, &d_columns, &kOne, Ld + inside, &d_rows, Ld, &d_rows, &kZero,
               C + inside, &below, 1, 1);
      }
      for (int j = 0; j < inside; ++j) {
        float* column = block + static_cast<ptrdiff_t>(to[j]) * rows;
        const float* c = C + static_cast<ptrdiff_t>(j) * below;
        for (int i = j; i < below; ++i) column[to[i]] -= c[i];
      }
    }
    if (columns <= kLoopColumns) {
      if (!factor_panel(block, rows, columns)) return false;
      continue;
    }
    int info = 0;
    spotrf_(&kLower, &columns, block, &rows, &info, 1);
    if (info != 0) return false;
    if (rows > columns) {
      const int rest = rows - columns;
      strsm_(&kRight, &kLower, &kTransposed, &kNo, &rest, &columns, &kOne, block, &rows, block + columns, &rows, 1, 1,
             1, 1);
    }
  }
  return true;
}

void solve_lower_single(const SupernodalPattern& p, const std::vector<float>& L, float* x) {
  std::vector<float> below;
  for (int s = 0; s < p.supernodes; ++s) {
    const int columns = p.column_count(s), rows = p.row_count(s), rest = rows - columns;
    const int* row = p.rows_of(s);
    const float* block = L.data() + p.value_start[s];
    float* own = x + p.super[s];
    if (columns <= kLoopColumns) {
      for (int j = 0; j < columns; ++j) {
        const float* column = block + static_cast<ptrdiff_t>(j) * rows;
        const float xj = own[j] / column[j];
        own[j] = xj;
        for (int i = j + 1; i < columns; ++i) own[i] -= column[i] * xj;
        for (int i = columns; i < rows; ++i) x[row[i]] -= column[i] * xj;
      }
      continue;
    }
    strsv_(&kLower, &kNo, &kNo, &columns, block, &rows, own, &kUnitStride, 1, 1, 1);
    if (rest == 0) continue;
    below.assign(static_cast<size_t>(rest), 0.0f);
    sgemv_(&kNo, &rest, &columns, &kOne, block + columns, &rows, own, &kUnitStride, &kZero, below.data(), &kUnitStride, 1);
    for (int i = 0; i < rest; ++i) x[row[columns + i]] -= below[static_cast<size_t>(i)];
  }
}

void solve_upper_single(const SupernodalPattern& p, const std::vector<float>& L, float* x) {
  std::vector<float> below;
  for (int s = p.supernodes - 1; s >= 0; --s) {
    const int columns = p.column_count(s), rows = p.row_count(s), rest = rows - columns;
    const int* row = p.rows_of(s);
    const float* block = L.data() + p.value_start[s];
    float* own = x + p.super[s];
    if (columns <= kLoopColumns) {
      for (int j = columns - 1; j >= 0; --j) {
        const float* column = block + static_cast<ptrdiff_t>(j) * rows;
        float sum = own[j];
        for (int i = j + 1; i < columns; ++i) sum -= column[i] * own[i];
        for (int i = columns; i < rows; ++i) sum -= column[i] * x[row[i]];
        own[j] = sum / column[j];
      }
      continue;
    }
    if (rest > 0) {
      below.resize(static_cast<size_t>(rest));
      for (int i = 0; i < rest; ++i) below[static_cast<size_t>(i)] = x[row[columns + i]];
      sgemv_(&kTransposed, &rest, &columns, &kMinusOne, block + columns, &rows, below.data(), &kUnitStride, &kOne, own,
             &kUnitStride, 1);
    }
    strsv_(&kLower, &kTransposed, &kNo, &columns, block, &rows, own, &kUnitStride, 1, 1, 1);
  }
}

} // namespace foldsketch
