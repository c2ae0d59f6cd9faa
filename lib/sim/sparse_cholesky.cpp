#include "sim/sparse_cholesky.h"

#include <chrono>

#include <cholmod.h>

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
} // namespace

struct SparseCholesky::State {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  bool numeric = false;
  State() {
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
