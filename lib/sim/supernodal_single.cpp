#include "sim/supernodal_single.h"

#include <algorithm>
#include <cstddef>

#include "sim/blas.h"

namespace foldsketch {
namespace {
const char kLower = 'L', kNo = 'N', kTransposed = 'T', kRight = 'R';
const float kOne = 1.0f, kZero = 0.0f, kMinusOne = -1.0f;
const int kUnitStride = 1;

void prepare(const SupernodalPattern& p, SupernodalWorkspace& work) {
  if (static_cast<int>(work.column_supernode.size()) == p.n && static_cast<int>(work.head.size()) == p.supernodes) return;
  work.row_map.assign(static_cast<size_t>(p.n), 0);
  work.column_supernode.assign(static_cast<size_t>(p.n), 0);
  size_t largest = 0;
  for (int s = 0; s < p.supernodes; ++s) {
    for (int j = p.super[s]; j < p.super[s + 1]; ++j) work.column_supernode[static_cast<size_t>(j)] = s;
    const auto rows = static_cast<size_t>(p.row_start[s + 1] - p.row_start[s]);
    largest = std::max(largest, rows * rows);
  }
  work.head.assign(static_cast<size_t>(p.supernodes), -1);
  work.next.assign(static_cast<size_t>(p.supernodes), -1);
  work.position.assign(static_cast<size_t>(p.supernodes), 0);
  work.update.assign(largest, 0.0f);
}

// Supernode s (columns k1 .. k2-1) has had its columns factorised down to row offset `from` in
// its row list: queue it on the supernode that holds its next row, which it updates next.
void queue(const SupernodalPattern& p, SupernodalWorkspace& w, int s, int from) {
  const int first = p.row_start[s];
  if (from >= p.row_start[s + 1] - first) return;
  const int target = w.column_supernode[static_cast<size_t>(p.rows[first + from])];
  w.position[static_cast<size_t>(s)] = from;
  w.next[static_cast<size_t>(s)] = w.head[static_cast<size_t>(target)];
  w.head[static_cast<size_t>(target)] = s;
}
} // namespace

bool factorize_single(const SupernodalPattern& p, const int* column_start, const int* row_index, const double* value,
                      std::vector<float>& L, SupernodalWorkspace& w) {
  prepare(p, w);
  L.resize(static_cast<size_t>(p.values));
  std::fill(w.head.begin(), w.head.end(), -1);
  for (int s = 0; s < p.supernodes; ++s) {
    const int k1 = p.super[s], k2 = p.super[s + 1], columns = k2 - k1;
    const int first_row = p.row_start[s], rows = p.row_start[s + 1] - first_row;
    float* block = L.data() + p.value_start[s];
    for (int i = 0; i < rows; ++i) w.row_map[static_cast<size_t>(p.rows[first_row + i])] = i;
    std::fill(block, block + static_cast<ptrdiff_t>(rows) * columns, 0.0f);
    for (int j = k1; j < k2; ++j) {
      float* column = block + static_cast<ptrdiff_t>(j - k1) * rows;
      for (int q = column_start[j]; q < column_start[j + 1]; ++q)
        column[w.row_map[static_cast<size_t>(row_index[q])]] = static_cast<float>(value[q]);
    }
    // Updates from every earlier supernode d whose next rows lie in this one's columns.
    int d = w.head[static_cast<size_t>(s)];
    w.head[static_cast<size_t>(s)] = -1;
    while (d >= 0) {
      const int after = w.next[static_cast<size_t>(d)];
      const int d_first = p.row_start[d], d_rows = p.row_start[d + 1] - d_first, d_columns = p.super[d + 1] - p.super[d];
      const int p1 = w.position[static_cast<size_t>(d)];
      int p2 = p1;
      while (p2 < d_rows && p.rows[d_first + p2] < k2) ++p2;
      const int inside = p2 - p1, below = d_rows - p1;  // rows in s's columns; rows from p1 on
      const float* Ld = L.data() + p.value_start[d] + p1;
      float* C = w.update.data();
      ssyrk_(&kLower, &kNo, &inside, &d_columns, &kOne, Ld, &d_rows, &kZero, C, &below, 1, 1);
      if (below > inside) {
        const int rest = below - inside;
        sgemm_(&kNo, &kTransposed, &rest, &inside, &d_columns, &kOne, Ld + inside, &d_rows, Ld, &d_rows, &kZero,
               C + inside, &below, 1, 1);
      }
      const int* d_row = p.rows + d_first + p1;
      for (int j = 0; j < inside; ++j) {
        float* column = block + static_cast<ptrdiff_t>(w.row_map[static_cast<size_t>(d_row[j])]) * rows;
        const float* c = C + static_cast<ptrdiff_t>(j) * below;
        for (int i = j; i < below; ++i) column[w.row_map[static_cast<size_t>(d_row[i])]] -= c[i];
      }
      queue(p, w, d, p2);
      d = after;
    }
    int info = 0;
    spotrf_(&kLower, &columns, block, &rows, &info, 1);
    if (info != 0) return false;
    if (rows > columns) {
      const int rest = rows - columns;
      strsm_(&kRight, &kLower, &kTransposed, &kNo, &rest, &columns, &kOne, block, &rows, block + columns, &rows, 1, 1,
             1, 1);
    }
    queue(p, w, s, columns);
  }
  return true;
}

void solve_lower_single(const SupernodalPattern& p, const std::vector<float>& L, float* x) {
  std::vector<float> below;
  for (int s = 0; s < p.supernodes; ++s) {
    const int k1 = p.super[s], columns = p.super[s + 1] - k1;
    const int first_row = p.row_start[s], rows = p.row_start[s + 1] - first_row, rest = rows - columns;
    const float* block = L.data() + p.value_start[s];
    strsv_(&kLower, &kNo, &kNo, &columns, block, &rows, x + k1, &kUnitStride, 1, 1, 1);
    if (rest == 0) continue;
    below.assign(static_cast<size_t>(rest), 0.0f);
    sgemv_(&kNo, &rest, &columns, &kOne, block + columns, &rows, x + k1, &kUnitStride, &kZero, below.data(),
           &kUnitStride, 1);
    for (int i = 0; i < rest; ++i) x[p.rows[first_row + columns + i]] -= below[static_cast<size_t>(i)];
  }
}

void solve_upper_single(const SupernodalPattern& p, const std::vector<float>& L, float* x) {
  std::vector<float> below;
  for (int s = p.supernodes - 1; s >= 0; --s) {
    const int k1 = p.super[s], columns = p.super[s + 1] - k1;
    const int first_row = p.row_start[s], rows = p.row_start[s + 1] - first_row, rest = rows - columns;
    const float* block = L.data() + p.value_start[s];
    if (rest > 0) {
      below.resize(static_cast<size_t>(rest));
      for (int i = 0; i < rest; ++i) below[static_cast<size_t>(i)] = x[p.rows[first_row + columns + i]];
      sgemv_(&kTransposed, &rest, &columns, &kMinusOne, block + columns, &rows, below.data(), &kUnitStride, &kOne,
             x + k1, &kUnitStride, 1);
    }
    strsv_(&kLower, &kTransposed, &kNo, &columns, block, &rows, x + k1, &kUnitStride, 1, 1, 1);
  }
}

} // namespace foldsketch
