#include "sim/sparse_cholesky.h"

#include <chrono>
#include <mutex>

#include <cholmod.h>
#include <dlfcn.h>

#include "core/error.h"

namespace foldsketch {
namespace {
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A CHOLMOD view (no copy) of an Eigen compressed column matrix, read as symmetric lower.
cholmod_sparse view(const Eigen::SparseMatrix<double>& A) {
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
// Runs the factorisation on the calling thread. Debian's CHOLMOD 3 (SuiteSparse 5.12) is built
// with OpenMP and a fixed team of CHOLMOD_OMP_NUM_THREADS = 4 for its copy and scatter loops,
// and OpenBLAS parks its own threads in a sched_yield loop between BLAS calls; on a 2-core
// machine the two pools and the engine's assembly threads fight for the cores and the kernel
// time exceeds the arithmetic. Measured on the warm 10K-triangle skirt re-drape
// (bench/drape_bench --starts warm, 123 Newton iterations): 12.75 s as shipped, 7.29 s with
// CHOLMOD's OpenMP off, 6.71 s with OpenBLAS on one thread as well (system time 20 s -> 0.4 s);
// at 20K, a second OpenBLAS thread saves 5 % of the factorisation time and costs 9 % overall.
// Both switches are process-wide library settings, looked up at run time so that a CHOLMOD
// without OpenMP or a BLAS other than OpenBLAS simply lacks them.
void run_factorisation_on_one_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    using SetInt = void (*)(int);
    // max-active-levels 0: every OpenMP parallel region runs on the thread that meets it.
    if (auto set_levels = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"))) set_levels(0);
    if (auto set_threads = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set_threads(1);
  });
}
} // namespace

struct SparseCholesky::State {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  bool numeric = false;
  State() {
    run_factorisation_on_one_thread();
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    // METIS beat AMD on cloth Hessians here (design notes, section 5).
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_METIS;
    common.postorder = 1;
    common.print = 0;
  }
  ~State() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

SparseCholesky::SparseCholesky() : state_(std::make_unique<State>()) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) throw ArgumentError("SparseCholesky: matrix must be compressed");
  const auto start = std::chrono::steady_clock::now();
  if (state_->factor) cholmod_free_factor(&state_->factor, &state_->common);
  cholmod_sparse a = view(A);
  state_->factor = cholmod_analyze(&a, &state_->common);
  if (!state_->factor) {  // no METIS in this CHOLMOD: let it choose (AMD)
    state_->common.nmethods = 0;
    state_->factor = cholmod_analyze(&a, &state_->common);
  }
  if (!state_->factor) throw std::runtime_error("CHOLMOD could not analyse the system");
  state_->numeric = false;
  analyze_seconds_ += seconds_since(start);
}

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& A) {
  if (!state_->factor) analyze(A);
  const auto start = std::chrono::steady_clock::now();
  cholmod_sparse a = view(A);
  cholmod_factorize(&a, state_->factor, &state_->common);
  ++factorizations_;
  factorize_seconds_ += seconds_since(start);
  state_->numeric = state_->common.status == CHOLMOD_OK && state_->factor->minor == state_->factor->n;
  return state_->numeric;
}

bool SparseCholesky::factorized() const { return state_->numeric; }

VectorXd SparseCholesky::solve(const VectorXd& b) const {
  if (!state_->numeric) throw std::logic_error("SparseCholesky::solve before a successful factorisation");
  const auto start = std::chrono::steady_clock::now();
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = static_cast<size_t>(b.size());
  rhs.d = static_cast<size_t>(b.size());
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, state_->factor, &rhs, &state_->common);
  VectorXd out = Eigen::Map<VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &state_->common);
  solve_seconds_ += seconds_since(start);
  return out;
}

} // namespace foldsketch
