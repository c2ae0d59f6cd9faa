// Sparse Cholesky of a Newton system on two cores. A vertex separator S (METIS's node
// bisection) splits the unknowns into halves D0 and D1 with no coupling between them. Each half
// is factorised with the separator last,
//   M_i = [A_ii A_iS; A_Si A_SS] = L_i L_i^T,   L_i = [L11 0; L21 L22],
// both at once on two threads; the separator's Schur complement is then dense and small:
//   S = A_SS - sum_i A_Si A_ii^-1 A_iS = L22_0 L22_0^T + L22_1 L22_1^T - A_SS,
// since L22_i L22_i^T = A_SS - A_Si A_ii^-1 A_iS. A is positive definite exactly when both M_i
// and S are (each M_i is if A is). Solves go through the halves' triangular factors and S.
//
// Why: one supernodal factorisation runs on one core (a second OpenBLAS thread saved 5 % of
// it; its supernodes are small), and it is 70-80 % of a drape's time. On the 20K-triangle skirt
// (29862 unknowns, separator 564 of them) one factorisation takes 0.095 s (1.6 Gflop); a half
// with the separator last 0.053 s (0.84 Gflop); in the drape, both halves at once and the
// separator take 0.058 s. Small systems are factorised whole (BisectedSettings::min_unknowns).
#pragma once

#include <memory>

#include <Eigen/SparseCore>

#include "core/types.h"
#include "sim/sparse_cholesky.h"

namespace foldsketch {

// A solve from a single-precision factor whose refined relative residual exceeds this is not
// to be trusted (BisectedCholesky::last_solve_trusted). The 20K-triangle skirt's re-drapes: at
// most 4e-4 (median 1e-6); the physics tests' stiff membranes under light loads: 0.3-12, i.e.
// no solve at all.
constexpr double kSingleSolveResidual = 1e-2;
// A solve whose refinement misses kSingleSolveResidual is rescued by conjugate gradients
// (BisectedSettings::rescue_iterations) down to this relative residual, the median refined
// residual of the 20K skirt's re-drapes (our choice: a Newton step needs no more).
constexpr double kRescuedSolveResidual = 1e-6;

struct BisectedSettings {
  // Below this many unknowns, one factorisation on one thread. The skirt drapes measured with
  // and without the split (same Newton iterations): 480 triangles (about 750 unknowns) even,
  // 1008 triangles 0.43 against 0.45 s, 2000 triangles 1.49 against 1.63 s; tiny systems
  // gain nothing from a second thread.
  int min_unknowns = 2000;
  // Split only when the separator is at most this fraction of the unknowns (a mesh that does
  // not bisect well, e.g. a long thin strip cut across, is still fine; a dense one is not).
  double max_separator_fraction = 0.1;
  // Single: the factorisation in single precision (about twice as fast), each solve then
  // refined in double precision against the factorised matrix this many times.
  FactorPrecision precision = FactorPrecision::Double;
  int refinements = 1;
  // When the refined residual still exceeds kSingleSolveResidual: at most this many conjugate
  // gradient iterations preconditioned by the factor before the solve is not trusted (each
  // costs one solve, about a twentieth of a factorisation at 20K triangles). The 20K skirt's
  // cold drape fell back to double precision at its 196th solve, where the refinement
  // diverged (0.026, 0.033, 0.038, ...), and every factorisation after it took twice as long.
  int rescue_iterations = 30;
};

class BisectedCholesky {
public:
  explicit BisectedCholesky(const BisectedSettings& settings = {});
  ~BisectedCholesky();
  BisectedCholesky(const BisectedCholesky&) = delete;
  BisectedCholesky& operator=(const BisectedCholesky&) = delete;

  // Symbolic analysis of A's pattern (symmetric; full or lower storage, the lower triangle is
  // read), the bisection included. Called again only when the pattern changes.
  void analyze(const Eigen::SparseMatrix<double>& A);
  // Whether the analysis in force is of A's pattern (false before any analysis). A caller that
  // is handed an analysed factorisation asks before reusing it.
  bool analysed_for(const Eigen::SparseMatrix<double>& A) const;
  // Numeric factorisation; false when A is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& A);
  bool factorized() const;
  VectorXd solve(const VectorXd& b) const;
  // |b - A x| / |b| of the last solve: computed only for single-precision factors (after
  // their refinements), 0 otherwise.
  double last_relative_residual() const { return last_relative_residual_; }
  // Whether the last solve can be used: false for a single-precision one whose refined (and
  // rescued) residual exceeds kSingleSolveResidual, whose matrix the rescue found indefinite
  // (last_solve_indefinite), or which does not even point along its right-hand side (b^T x
  // <= 0, impossible for a positive definite A: the stiff catenary strip's Newton step once did
  // so at a refined residual of 0.0096). Its callers then factorise in double precision, or,
  // for an indefinite matrix, treat the factorisation as refused.
  // Always true in double precision.
  bool last_solve_trusted() const { return last_solve_trusted_; }
  // Whether the last solve found the factorised matrix not positive definite (a direction of
  // negative curvature in the rescue's conjugate gradients): a single-precision factorisation
  // can succeed on a matrix whose smallest eigenvalue is negative but below its rounding. The
  // solve is then not trusted, and its callers treat the factorisation as failed.
  bool last_solve_indefinite() const { return last_solve_indefinite_; }
  // Takes effect at the next factorisation; the analysis is kept.
  void set_precision(FactorPrecision precision) { settings_.precision = precision; }
  FactorPrecision precision() const { return settings_.precision; }
  void set_rescue_iterations(int iterations) { settings_.rescue_iterations = iterations; }

  bool split() const;        // factorised as two halves (else whole)
  int separator_size() const;
  int factorizations() const { return factorizations_; }
  // Conjugate gradient iterations spent rescuing single-precision solves (rescue_iterations).
  int rescue_iterations() const { return rescue_iterations_; }
  double analyze_seconds() const { return analyze_seconds_; }
  double factorize_seconds() const { return factorize_seconds_; }
  double solve_seconds() const { return solve_seconds_; }

private:
  VectorXd solve_once(const VectorXd& b) const;
  struct State;
  std::unique_ptr<State> state_;
  BisectedSettings settings_;
  int factorizations_ = 0;
  double analyze_seconds_ = 0, factorize_seconds_ = 0;
  mutable double solve_seconds_ = 0;
  mutable double last_relative_residual_ = 0;
  mutable bool last_solve_trusted_ = true;
  mutable int rescue_iterations_ = 0;
  mutable bool last_solve_indefinite_ = false;
};

} // namespace foldsketch
