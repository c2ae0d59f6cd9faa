#include "sim/bisected_cholesky.h"

#include <algorithm>
#include <array>
#include <exception>
#include <thread>
#include <vector>

#include <cholmod.h>

#include "core/error.h"
#include "sim/blas.h"
#include "sim/cholmod_view.h"
#include "sim/sparse_cholesky.h"

namespace foldsketch {
namespace {
// One half: M = A's principal submatrix on its own unknowns and the separator's (local index:
// the half's unknowns in ascending order, then the separator's), lower storage.
struct Half {
  std::vector<int> unknowns;        // A's rows, ascending
  Eigen::SparseMatrix<double> M;
  std::vector<long> from;           // per stored value of M, the value index in A
  std::vector<int> factor_rows;     // per factor position, A's row (the separator's last)
  SparseCholesky cholesky;
  Eigen::MatrixXd L22;              // the factor's separator block
};
} // namespace

struct BisectedCholesky::State {
  cholmod_common common{};
  bool analysed = false;
  Eigen::Index nonzeros = 0;        // of the analysed pattern
  std::vector<int> outer, inner;    // the analysed pattern (compressed columns)
  bool split = false;
  bool numeric = false;
  bool single = false;              // the factorisation in force is single precision
  SparseCholesky whole;
  std::array<Half, 2> halves;
  std::vector<int> separator;       // A's rows, ascending
  std::vector<std::array<long, 3>> separator_values;  // (value index in A, row, column) of A_SS's lower triangle
  Eigen::MatrixXd schur;            // Cholesky factor of the separator's Schur complement (lower)
  Eigen::SparseMatrix<double> matrix;  // the factorised matrix, for refining single-precision solves
  State() { cholmod_start(&common); }
  ~State() { cholmod_finish(&common); }
};

BisectedCholesky::BisectedCholesky(const BisectedSettings& settings) : state_(std::make_unique<State>()), settings_(settings) {}
BisectedCholesky::~BisectedCholesky() = default;

bool BisectedCholesky::split() const { return state_->split; }
int BisectedCholesky::separator_size() const { return static_cast<int>(state_->separator.size()); }
bool BisectedCholesky::factorized() const { return state_->numeric; }

void BisectedCholesky::analyze(const Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) throw ArgumentError("BisectedCholesky: matrix must be compressed");
  const auto start = std::chrono::steady_clock::now();
  State& st = *state_;
  st.numeric = false;
  st.split = false;
  st.analysed = true;
  st.nonzeros = A.nonZeros();
  st.outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  st.inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  st.matrix = Eigen::SparseMatrix<double>();  // another pattern: copied whole at the next single factorisation
  const int n = static_cast<int>(A.rows());
  const bool two_cores = std::thread::hardware_concurrency() >= 2;
  std::vector<int> part(static_cast<size_t>(n), 0);
  if (two_cores && n >= settings_.min_unknowns) {
    keep_factorisation_on_this_thread();
    cholmod_sparse a = cholmod_lower_view(A);
    const long separator = cholmod_bisect(&a, nullptr, 0, /*compress=*/1, part.data(), &st.common);
    const auto left = std::count(part.begin(), part.end(), 0), right = std::count(part.begin(), part.end(), 1);
    st.split = st.common.status == CHOLMOD_OK && separator > 0 && left > 0 && right > 0 &&
               static_cast<double>(separator) <= settings_.max_separator_fraction * n;
  }
  if (!st.split) {
    st.whole.analyze(A);
    analyze_seconds_ += seconds_since(start);
    return;
  }

  st.separator.clear();
  for (Half& h : st.halves) h.unknowns.clear();
  for (int i = 0; i < n; ++i)
    (part[static_cast<size_t>(i)] == 2 ? st.separator : st.halves[static_cast<size_t>(part[static_cast<size_t>(i)])].unknowns).push_back(i);
  const int s = static_cast<int>(st.separator.size());
  std::vector<int> separator_index(static_cast<size_t>(n), -1);
  for (int k = 0; k < s; ++k) separator_index[static_cast<size_t>(st.separator[static_cast<size_t>(k)])] = k;
  // A_SS's lower triangle, in separator indices.
  st.separator_values.clear();
  for (int j = 0; j < n; ++j)
    for (int q = A.outerIndexPtr()[j]; q < A.outerIndexPtr()[j + 1]; ++q) {
      const int i = A.innerIndexPtr()[q];
      if (i < j) continue;
      const int r = separator_index[static_cast<size_t>(i)], c = separator_index[static_cast<size_t>(j)];
      if (r >= 0 && c >= 0) st.separator_values.push_back({q, std::max(r, c), std::min(r, c)});
    }

  for (size_t side = 0; side < 2; ++side) {
    Half& h = st.halves[side];
    const int m = static_cast<int>(h.unknowns.size());
    std::vector<int> local(static_cast<size_t>(n), -1);
    for (int k = 0; k < m; ++k) local[static_cast<size_t>(h.unknowns[static_cast<size_t>(k)])] = k;
    for (int k = 0; k < s; ++k) local[static_cast<size_t>(st.separator[static_cast<size_t>(k)])] = m + k;
    // M's lower triangle; each value carries its index in A until the pattern is built.
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<Eigen::Triplet<double>> interior;  // the half's own block, for its ordering
    for (int j = 0; j < n; ++j)
      for (int q = A.outerIndexPtr()[j]; q < A.outerIndexPtr()[j + 1]; ++q) {
        const int i = A.innerIndexPtr()[q];
        if (i < j) continue;
        const int r = local[static_cast<size_t>(i)], c = local[static_cast<size_t>(j)];
        if (r < 0 || c < 0) {
          if ((r < 0) != (c < 0) && part[static_cast<size_t>(i)] != 2 && part[static_cast<size_t>(j)] != 2)
            throw std::logic_error("BisectedCholesky: the two halves are coupled");
          continue;
        }
        entries.emplace_back(std::max(r, c), std::min(r, c), static_cast<double>(q));
        if (r < m && c < m) interior.emplace_back(std::max(r, c), std::min(r, c), 1.0);
      }
    h.M = Eigen::SparseMatrix<double>(m + s, m + s);
    h.M.setFromTriplets(entries.begin(), entries.end());
    h.M.makeCompressed();
    h.from.resize(static_cast<size_t>(h.M.nonZeros()));
    for (long k = 0; k < h.M.nonZeros(); ++k) h.from[static_cast<size_t>(k)] = static_cast<long>(h.M.valuePtr()[k]);
    // Fill-reducing ordering of the half's own unknowns (METIS), then the separator.
    Eigen::SparseMatrix<double> own(m, m);
    own.setFromTriplets(interior.begin(), interior.end());
    own.makeCompressed();
    std::vector<int> order(static_cast<size_t>(m));
    cholmod_sparse o = cholmod_lower_view(own);
    if (!cholmod_metis(&o, nullptr, 0, /*postorder=*/1, order.data(), &st.common)) {
      // No METIS in this CHOLMOD: the natural order (still correct, more fill).
      for (int k = 0; k < m; ++k) order[static_cast<size_t>(k)] = k;
    }
    std::vector<int> ordering = order;
    for (int k = 0; k < s; ++k) ordering.push_back(m + k);
    h.factor_rows.resize(ordering.size());
    for (size_t k = 0; k < ordering.size(); ++k) {
      const int l = ordering[k];
      h.factor_rows[k] = l < m ? h.unknowns[static_cast<size_t>(l)] : st.separator[static_cast<size_t>(l - m)];
    }
    h.cholesky.analyze(h.M, ordering);
  }
  analyze_seconds_ += seconds_since(start);
}

bool BisectedCholesky::analysed_for(const Eigen::SparseMatrix<double>& A) const {
  const State& st = *state_;
  return st.analysed && A.isCompressed() && A.nonZeros() == st.nonzeros &&
         static_cast<size_t>(A.outerSize()) + 1 == st.outer.size() &&
         std::equal(st.outer.begin(), st.outer.end(), A.outerIndexPtr()) &&
         std::equal(st.inner.begin(), st.inner.end(), A.innerIndexPtr());
}

bool BisectedCholesky::factorize(const Eigen::SparseMatrix<double>& A) {
  State& st = *state_;
  if (!st.analysed) analyze(A);
  if (st.split && A.nonZeros() != st.nonzeros)
    throw ArgumentError("BisectedCholesky::factorize: the matrix's pattern is not the analysed one");
  const auto start = std::chrono::steady_clock::now();
  ++factorizations_;
  st.single = settings_.precision == FactorPrecision::Single;
  st.whole.set_precision(settings_.precision);
  for (Half& h : st.halves) h.cholesky.set_precision(settings_.precision);
  if (st.single) {  // kept for refining the solves
    if (st.matrix.nonZeros() != A.nonZeros())
      st.matrix = A;
    else
      std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), st.matrix.valuePtr());
  }
  if (!st.split) {
    st.numeric = st.whole.factorize(A);
    factorize_seconds_ += seconds_since(start);
    return st.numeric;
  }
  st.numeric = false;
  const double* values = A.valuePtr();
  const int s = static_cast<int>(st.separator.size());
  // Each half: its values, its factorisation, and its separator block's product L22 L22^T.
  const auto work = [&](Half& h, Eigen::MatrixXd& product) {
    double* m = h.M.valuePtr();
    for (size_t k = 0; k < h.from.size(); ++k) m[k] = values[h.from[k]];
    if (!h.cholesky.factorize(h.M)) return false;
    h.L22 = h.cholesky.trailing_block(s);
    const char lower = 'L', no = 'N';
    if (st.single) {  // as precise as the halves' factors, at twice the speed
      const Eigen::MatrixXf L22 = h.L22.cast<float>();
      Eigen::MatrixXf p = Eigen::MatrixXf::Zero(s, s);
      const float one = 1.0f, zero = 0.0f;
      ssyrk_(&lower, &no, &s, &s, &one, L22.data(), &s, &zero, p.data(), &s, 1, 1);
      product = p.cast<double>();
      return true;
    }
    product = Eigen::MatrixXd::Zero(s, s);
    const double one = 1.0, zero = 0.0;
    dsyrk_(&lower, &no, &s, &s, &one, h.L22.data(), &s, &zero, product.data(), &s, 1, 1);
    return true;
  };
  std::array<Eigen::MatrixXd, 2> products;
  bool ok1 = false;
  std::exception_ptr error;
  std::thread other([&] {
    try {
      ok1 = work(st.halves[1], products[1]);
    } catch (...) {
      error = std::current_exception();
    }
  });
  bool ok0 = false;
  try {
    ok0 = work(st.halves[0], products[0]);
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (error) std::rethrow_exception(error);
  if (ok0 && ok1) {
    // S = L22_0 L22_0^T + L22_1 L22_1^T - A_SS (lower triangle), then S = C C^T.
    st.schur = products[0] + products[1];
    for (const auto& [q, r, c] : st.separator_values) st.schur(r, c) -= values[q];
    const char lower = 'L';
    int info = 0;
    if (st.single) {
      Eigen::MatrixXf schur = st.schur.cast<float>();
      spotrf_(&lower, &s, schur.data(), &s, &info, 1);
      st.schur = schur.cast<double>();
    } else {
      dpotrf_(&lower, &s, st.schur.data(), &s, &info, 1);
    }
    st.numeric = info == 0;
  }
  factorize_seconds_ += seconds_since(start);
  return st.numeric;
}

VectorXd BisectedCholesky::solve(const VectorXd& b) const {
  // A single-precision factor's solve has a relative error of about cond(A) 6e-8; each
  // refinement against the double-precision matrix multiplies it by about as much again.
  VectorXd x = solve_once(b);
  last_relative_residual_ = 0;
  last_solve_trusted_ = true;
  last_solve_indefinite_ = false;
  if (!state_->single) return x;
  const auto A = state_->matrix.selfadjointView<Eigen::Lower>();
  VectorXd r = b - A * x;
  for (int k = 0; k < settings_.refinements; ++k) {
    x += solve_once(r);
    r = b - A * x;
  }
  const double b_norm = b.norm();
  const double scale = b_norm > 0 ? b_norm : 1.0;
  last_relative_residual_ = r.norm() / scale;
  if (last_relative_residual_ > kSingleSolveResidual && settings_.rescue_iterations > 0) {
    // The refinement did not get there (near-singular systems, where it may even diverge):
    // conjugate gradients preconditioned by the single-precision factor, which is positive
    // definite, converge where the refinement's fixed-point iteration does not.
    VectorXd z = solve_once(r), p = z;
    double rz = r.dot(z);
    for (int k = 0; k < settings_.rescue_iterations && last_relative_residual_ > kRescuedSolveResidual; ++k) {
      const VectorXd Ap = A * p;
      const double pAp = p.dot(Ap);
      if (!(pAp > 0.0) || !(rz > 0.0)) {
        // A direction of negative curvature: the matrix is not positive definite, and the
        // single-precision factorisation's rounding let it pass.
        last_solve_indefinite_ = true;
        break;
      }
      const double step = rz / pAp;
      x += step * p;
      r -= step * Ap;
      last_relative_residual_ = r.norm() / scale;
      z = solve_once(r);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
      ++rescue_iterations_;
    }
    r = b - A * x;  // the true residual, not the recurrence's
    last_relative_residual_ = r.norm() / scale;
  }
  last_solve_trusted_ = !last_solve_indefinite_ && last_relative_residual_ <= kSingleSolveResidual && b.dot(x) > 0.0;
  return x;
}

VectorXd BisectedCholesky::solve_once(const VectorXd& b) const {
  const State& st = *state_;
  if (!st.numeric) throw std::logic_error("BisectedCholesky::solve before a successful factorisation");
  if (!st.split) return st.whole.solve(b);
  const auto start = std::chrono::steady_clock::now();
  const int s = static_cast<int>(st.separator.size());
  // Forward: z_i = L_i^-1 [b_i; 0]. Its separator part is z_iS = -L22^-1 A_Si A_ii^-1 b_i, so
  // r = b_S - sum_i A_Si A_ii^-1 b_i = b_S + sum_i L22 z_iS.
  std::array<VectorXd, 2> z;
  const auto forward = [&](int side) {
    const Half& h = st.halves[static_cast<size_t>(side)];
    const int m = static_cast<int>(h.unknowns.size());
    VectorXd y = VectorXd::Zero(m + s);
    for (int k = 0; k < m; ++k) y(k) = b(h.factor_rows[static_cast<size_t>(k)]);
    z[static_cast<size_t>(side)] = h.cholesky.solve_lower(y);
  };
  std::thread other(forward, 1);
  forward(0);
  other.join();
  VectorXd r(s);
  for (int k = 0; k < s; ++k) r(k) = b(st.separator[static_cast<size_t>(k)]);
  for (size_t side = 0; side < 2; ++side) {
    const Half& h = st.halves[side];
    r += h.L22.triangularView<Eigen::Lower>() * z[side].tail(s);
  }
  // x_S = S^-1 r.
  const auto C = st.schur.triangularView<Eigen::Lower>();
  VectorXd xs = C.solve(r);
  C.transpose().solveInPlace(xs);
  // Backward: L_i^T [u; v] = [z_i own; L22^T x_S] gives v = x_S and u the half's unknowns.
  VectorXd x(b.size());
  for (int k = 0; k < s; ++k) x(st.separator[static_cast<size_t>(k)]) = xs(k);
  const auto backward = [&](int side) {
    const Half& h = st.halves[static_cast<size_t>(side)];
    const int m = static_cast<int>(h.unknowns.size());
    VectorXd w(m + s);
    w.head(m) = z[static_cast<size_t>(side)].head(m);
    w.tail(s) = h.L22.transpose().triangularView<Eigen::Upper>() * xs;
    const VectorXd u = h.cholesky.solve_upper(w);
    for (int k = 0; k < m; ++k) x(h.factor_rows[static_cast<size_t>(k)]) = u(k);
  };
  std::thread other_back(backward, 1);
  backward(0);
  other_back.join();
  solve_seconds_ += seconds_since(start);
  return x;
}

} // namespace foldsketch
