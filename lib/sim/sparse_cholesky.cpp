#include "sim/sparse_cholesky.h"

#include <algorithm>
#include <chrono>
#include <tuple>
#include <vector>
#include <mutex>

#include <cholmod.h>
#include <dlfcn.h>

#include "core/error.h"
#include "sim/cholmod_view.h"
#include "sim/supernodal_single.h"

namespace foldsketch {
namespace {
using SetInt = void (*)(int);
} // namespace

// Runs the factorisation on the calling thread. Debian's CHOLMOD 3 (SuiteSparse 5.12) is built
// with OpenMP and a fixed team of CHOLMOD_OMP_NUM_THREADS = 4 for its copy and scatter loops,
// and OpenBLAS parks its own threads in a sched_yield loop between BLAS calls; on a 2-core
// machine the two pools and the engine's assembly threads fight for the cores and the kernel
// time exceeds the arithmetic. Measured on the warm 10K-triangle skirt re-drape
// (bench/drape_bench --starts warm, 123 Newton iterations): 12.75 s as shipped, 7.29 s with
// CHOLMOD's OpenMP off, 6.71 s with OpenBLAS on one thread as well (system time 20 s -> 0.4 s);
// at 20K, a second OpenBLAS thread saves 5 % of the factorisation time and costs 9 % overall.
// OpenBLAS's switch is process-wide, OpenMP's per thread (below); both are looked up at run
// time so that a CHOLMOD without OpenMP or a BLAS other than OpenBLAS simply lacks them.
void keep_factorisation_on_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (auto set_threads = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set_threads(1);
  });
  // max-active-levels 0: every OpenMP parallel region runs on the thread that meets it. An
  // OpenMP setting of the calling thread: a thread that did not make it spawns CHOLMOD's team
  // of 4 (two factorisations at once on 2 cores then took 2.3x as long each).
  static const auto set_levels = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (set_levels) set_levels(0);
}

struct SparseCholesky::State {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  bool numeric = false;
  // The lower triangle of P A P' (P the fill-reducing permutation of `factor`), the matrix the
  // supernodal factorisation reads, and where each stored value of A goes in it (-1: A's upper
  // triangle, not read). cholmod_factorize would build it anew from a lower-stored A with two
  // permuted transposes per call (allocated, filled and freed): 7 % of a warm 10K-triangle
  // drape's profile (perf, cholmod_transpose_sym). The pattern is fixed between analyses, so
  // the permutation is a gather of the values.
  cholmod_sparse* permuted = nullptr;
  std::vector<long> destination;
  // Single precision: the factor's values and the factorisation's workspace.
  std::vector<float> single;
  bool single_numeric = false;      // the last factorisation was in single precision
  SupernodalWorkspace workspace;
  SupernodalPattern pattern() const {
    SupernodalPattern p;
    p.n = static_cast<int>(factor->n);
    p.supernodes = static_cast<int>(factor->nsuper);
    p.super = static_cast<const int*>(factor->super);
    p.row_start = static_cast<const int*>(factor->pi);
    p.value_start = static_cast<const int*>(factor->px);
    p.rows = static_cast<const int*>(factor->s);
    p.values = static_cast<long>(factor->xsize);
    return p;
  }
  State() {
    keep_factorisation_on_this_thread();
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    // METIS beat AMD on cloth Hessians here (design notes, section 5).
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_METIS;
    common.postorder = 1;
    common.print = 0;
  }
  ~State() {
    if (permuted) cholmod_free_sparse(&permuted, &common);
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

SparseCholesky::SparseCholesky(FactorPrecision precision) : state_(std::make_unique<State>()), precision_(precision) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& A) { analyze_with(A, nullptr); }

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& A, const std::vector<int>& ordering) {
  if (ordering.size() != static_cast<size_t>(A.rows())) throw ArgumentError("SparseCholesky: ordering has the wrong size");
  analyze_with(A, &ordering);
}

void SparseCholesky::analyze_with(const Eigen::SparseMatrix<double>& A, const std::vector<int>* ordering) {
  if (!A.isCompressed()) throw ArgumentError("SparseCholesky: matrix must be compressed");
  const auto start = std::chrono::steady_clock::now();
  keep_factorisation_on_this_thread();
  if (state_->factor) cholmod_free_factor(&state_->factor, &state_->common);
  cholmod_sparse a = cholmod_lower_view(A);
  cholmod_common& c = state_->common;
  if (ordering) {
    // As given: no postordering either, so that the factor's columns keep the given order.
    const auto saved = std::make_tuple(c.nmethods, c.method[0].ordering, c.postorder);
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    c.postorder = 0;
    state_->factor = cholmod_analyze_p(&a, const_cast<int*>(ordering->data()), nullptr, 0, &c);
    std::tie(c.nmethods, c.method[0].ordering, c.postorder) = saved;
    if (state_->factor && !std::equal(ordering->begin(), ordering->end(), static_cast<const int*>(state_->factor->Perm)))
      throw std::logic_error("SparseCholesky: CHOLMOD changed the given ordering");
  } else {
    state_->factor = cholmod_analyze(&a, &c);
    if (!state_->factor) {  // no METIS in this CHOLMOD: let it choose (AMD)
      c.nmethods = 0;
      state_->factor = cholmod_analyze(&a, &c);
    }
  }
  if (!state_->factor) throw std::runtime_error("CHOLMOD could not analyse the system");
  if (!state_->factor->is_super) throw std::logic_error("SparseCholesky: CHOLMOD made no supernodal analysis");
  state_->workspace = {};
  build_permuted(A);
  state_->numeric = false;
  analyze_seconds_ += seconds_since(start);
}

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& A) {
  if (!state_->factor) analyze(A);
  const auto start = std::chrono::steady_clock::now();
  keep_factorisation_on_this_thread();
  if (A.nonZeros() != static_cast<Eigen::Index>(state_->destination.size()))
    throw ArgumentError("SparseCholesky::factorize: the matrix's pattern is not the analysed one");
  cholmod_sparse* s = state_->permuted;
  double* sx = static_cast<double*>(s->x);
  const double* ax = A.valuePtr();
  const long* to = state_->destination.data();
  for (size_t k = 0; k < state_->destination.size(); ++k)
    if (to[k] >= 0) sx[to[k]] = ax[k];
  state_->single_numeric = precision_ == FactorPrecision::Single;
  if (state_->single_numeric) {
    state_->numeric = factorize_single(state_->pattern(), static_cast<const int*>(s->p), static_cast<const int*>(s->i),
                                       sx, state_->single, state_->workspace);
  } else {
    double beta[2] = {0, 0};
    cholmod_super_numeric(s, nullptr, beta, state_->factor, &state_->common);
    state_->numeric = state_->common.status == CHOLMOD_OK && state_->factor->minor == state_->factor->n;
  }
  ++factorizations_;
  factorize_seconds_ += seconds_since(start);
  return state_->numeric;
}

void SparseCholesky::build_permuted(const Eigen::SparseMatrix<double>& A) {
  State& st = *state_;
  if (st.permuted) cholmod_free_sparse(&st.permuted, &st.common);
  const int n = static_cast<int>(A.rows());
  std::vector<int> inverse(static_cast<size_t>(n));
  const int* perm = static_cast<const int*>(st.factor->Perm);
  for (int k = 0; k < n; ++k) inverse[static_cast<size_t>(perm ? perm[k] : k)] = k;
  // Entry (i, j), i >= j, of A lands at (max, min) of (inverse[i], inverse[j]) in P A P'.
  const auto nnz = static_cast<size_t>(A.nonZeros());
  std::vector<int> row(nnz, -1), col(nnz, -1);
  std::vector<long> count(static_cast<size_t>(n) + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int k = A.outerIndexPtr()[j]; k < A.outerIndexPtr()[j + 1]; ++k) {
      const int i = A.innerIndexPtr()[k];
      if (i < j) continue;
      const int a = inverse[static_cast<size_t>(i)], b = inverse[static_cast<size_t>(j)];
      row[static_cast<size_t>(k)] = std::max(a, b);
      col[static_cast<size_t>(k)] = std::min(a, b);
      ++count[static_cast<size_t>(col[static_cast<size_t>(k)]) + 1];
    }
  for (int j = 0; j < n; ++j) count[static_cast<size_t>(j) + 1] += count[static_cast<size_t>(j)];
  const long stored = count[static_cast<size_t>(n)];
  st.permuted = cholmod_allocate_sparse(static_cast<size_t>(n), static_cast<size_t>(n), static_cast<size_t>(stored),
                                        /*sorted=*/1, /*packed=*/1, /*stype=*/-1, CHOLMOD_REAL, &st.common);
  if (!st.permuted) throw std::runtime_error("CHOLMOD could not allocate the permuted system");
  int* sp = static_cast<int*>(st.permuted->p);
  int* si = static_cast<int*>(st.permuted->i);
  for (int j = 0; j <= n; ++j) sp[j] = static_cast<int>(count[static_cast<size_t>(j)]);
  // Counting sort by column, then each column by row.
  std::vector<long> next(count.begin(), count.end() - 1), source(static_cast<size_t>(stored));
  for (size_t k = 0; k < nnz; ++k)
    if (col[k] >= 0) source[static_cast<size_t>(next[static_cast<size_t>(col[k])]++)] = static_cast<long>(k);
  for (int j = 0; j < n; ++j)
    std::sort(source.begin() + sp[j], source.begin() + sp[j + 1],
              [&](long x, long y) { return row[static_cast<size_t>(x)] < row[static_cast<size_t>(y)]; });
  st.destination.assign(nnz, -1);
  for (long q = 0; q < stored; ++q) {
    const auto k = static_cast<size_t>(source[static_cast<size_t>(q)]);
    si[q] = row[k];
    st.destination[k] = q;
  }
}

bool SparseCholesky::factorized() const { return state_->numeric; }

VectorXd SparseCholesky::solve(const VectorXd& b) const { return solve_system(CHOLMOD_A, b); }
VectorXd SparseCholesky::solve_lower(const VectorXd& b) const { return solve_system(CHOLMOD_L, b); }
VectorXd SparseCholesky::solve_upper(const VectorXd& b) const { return solve_system(CHOLMOD_Lt, b); }

Eigen::MatrixXd SparseCholesky::trailing_block(int m) const {
  if (!state_->numeric) throw std::logic_error("SparseCholesky::trailing_block before a successful factorisation");
  const cholmod_factor& L = *state_->factor;
  const auto n = static_cast<int>(L.n);
  if (m < 0 || m > n) throw ArgumentError("SparseCholesky::trailing_block: block larger than the factor");
  const int first = n - m;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m, m);
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  const auto* rows = static_cast<const int*>(L.s);
  const bool single = state_->single_numeric;
  const auto* x = static_cast<const double*>(L.x);
  const float* xs = state_->single.data();
  // Supernode k holds columns super[k] .. super[k+1]-1 as a dense column-major block over its
  // row indices rows[pi[k] .. pi[k+1]-1], the diagonal block first.
  for (size_t k = 0; k < L.nsuper; ++k) {
    if (super[k + 1] <= first) continue;
    const int row_count = pi[k + 1] - pi[k];
    for (int col = std::max(super[k], first); col < super[k + 1]; ++col) {
      const int j = col - super[k];
      for (int r = j; r < row_count; ++r) {
        const long at = px[k] + static_cast<long>(j) * row_count + r;
        out(rows[pi[k] + r] - first, col - first) = single ? static_cast<double>(xs[at]) : x[at];
      }
    }
  }
  return out;
}

VectorXd SparseCholesky::solve_system(int system, const VectorXd& b) const {
  if (!state_->numeric) throw std::logic_error("SparseCholesky::solve before a successful factorisation");
  if (state_->single_numeric) return solve_single(system, b);
  const auto start = std::chrono::steady_clock::now();
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = static_cast<size_t>(b.size());
  rhs.d = static_cast<size_t>(b.size());
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(system, state_->factor, &rhs, &state_->common);
  VectorXd out = Eigen::Map<VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &state_->common);
  solve_seconds_ += seconds_since(start);
  return out;
}

VectorXd SparseCholesky::solve_single(int system, const VectorXd& b) const {
  const auto start = std::chrono::steady_clock::now();
  const SupernodalPattern p = state_->pattern();
  const auto n = static_cast<size_t>(b.size());
  std::vector<float> y(n);
  const int* perm = static_cast<const int*>(state_->factor->Perm);
  const bool permute = system == CHOLMOD_A && perm;
  for (size_t k = 0; k < n; ++k) y[k] = static_cast<float>(b(permute ? perm[k] : static_cast<Eigen::Index>(k)));
  if (system != CHOLMOD_Lt) solve_lower_single(p, state_->single, y.data());
  if (system != CHOLMOD_L) solve_upper_single(p, state_->single, y.data());
  VectorXd out(b.size());
  for (size_t k = 0; k < n; ++k) out(permute ? perm[k] : static_cast<Eigen::Index>(k)) = y[k];
  solve_seconds_ += seconds_since(start);
  return out;
}

} // namespace foldsketch
