#include "sim/stability.h"

#include <cmath>
#include <limits>

namespace foldsketch {
namespace {

// Inverse iteration steps for the lowest mode, and the relative change of its Rayleigh
// quotient at which it stops: the escape needs a direction of negative curvature, not an
// accurate eigenvector.
constexpr int kInverseIterations = 50;
constexpr double kRayleighTolerance = 1e-4;
// Shifts tried to make H + shift M positive definite grow by this factor, up to the bound.
constexpr double kShiftGrowth = 4.0, kLargestShift = 1e12;

} // namespace

namespace {
StabilityCheck check_in_double(const ClothEnergy& energy, SparseMatrix& hessian, BisectedCholesky& cholesky) {
  StabilityCheck check;
  const VectorXd& mass = energy.free_mass();
  if (mass.size() == 0) return check;
  double applied = kNeutralCurvature;
  energy.add_mass(hessian, applied);
  ++check.factorizations;
  if (cholesky.factorize(hessian)) return check;
  // Indefinite: grow the shift until H + shift M is positive definite.
  double shift = applied;
  for (;;) {
    shift *= kShiftGrowth;
    if (shift > kLargestShift) {
      check.stable = false;
      check.lowest_eigenvalue = -std::numeric_limits<double>::infinity();
      return check;  // no direction found: the caller reports the drape unstable
    }
    energy.add_mass(hessian, shift - applied);
    applied = shift;
    ++check.factorizations;
    if (cholesky.factorize(hessian)) break;
  }
  // Inverse iteration with (H + shift M)^-1 M: its largest eigenvalue 1 / (lambda + shift)
  // belongs to the most negative lambda of M^-1 H, and the shift is at most kShiftGrowth times
  // past it, so each step gains at least that factor over the other modes.
  VectorXd v(mass.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = std::sin(1.0 + 12.9898 * static_cast<double>(i));  // deterministic, no symmetry
  v /= std::sqrt(v.dot(mass.cwiseProduct(v)));
  double lambda = 0;
  for (int k = 0; k < kInverseIterations; ++k) {
    VectorXd w = cholesky.solve(mass.cwiseProduct(v));
    const double norm = std::sqrt(w.dot(mass.cwiseProduct(w)));
    if (!(norm > 0) || !std::isfinite(norm)) break;
    v = w / norm;
    // Rayleigh quotient of M^-1 H: v^T (H + shift M) v - shift, v of unit M-norm.
    const double next = v.dot(hessian * v) - shift;
    const bool settled = k > 0 && std::abs(next - lambda) <= kRayleighTolerance * std::abs(next);
    lambda = next;
    if (settled) break;
  }
  // The refused factorisation is the proof of instability; the Rayleigh quotient is an upper
  // bound on the lowest eigenvalue, and its vector a way out only where it curves downwards.
  check.stable = false;
  check.lowest_eigenvalue = lambda;
  if (lambda < 0.0) check.mode = v;
  return check;
}
} // namespace

StabilityCheck check_stability(const ClothEnergy& energy, SparseMatrix& hessian, BisectedCholesky& cholesky) {
  // The verdict in double precision: a single-precision Cholesky can refuse a positive definite
  // matrix once its condition number passes about 1e7 (DrapeSettings::factor_precision).
  struct Restore {
    BisectedCholesky& cholesky;
    FactorPrecision precision;
    ~Restore() { cholesky.set_precision(precision); }
  } restore{cholesky, cholesky.precision()};
  cholesky.set_precision(FactorPrecision::Double);
  return check_in_double(energy, hessian, cholesky);
}

StabilityCheck check_stability(ClothEnergy& energy, const MatrixX3d& x) {
  energy.prepare(x);
  SparseMatrix hessian = energy.pattern();
  energy.evaluate(x, nullptr, &hessian, HessianKind::Exact);
  BisectedCholesky cholesky;
  cholesky.analyze(hessian);
  return check_stability(energy, hessian, cholesky);
}

} // namespace foldsketch
