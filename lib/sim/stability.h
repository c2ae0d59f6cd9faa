// Whether a static equilibrium is stable, and the way out of one that is not.
//
// Why: Newton's method stops at any point where the forces vanish, and a saddle of the energy
// is such a point. A start with a symmetry the forces keep (a flat sheet squeezed in its own
// plane, a disc laid flat on the Cusick tester) has forces that never leave it, so the solver
// can converge to the symmetric state although any disturbance would buckle it. A drape there
// is not one a real garment takes. At a stable equilibrium the exact Hessian H is positive
// semi-definite; we ask that H + shift M be positive definite (M the lumped mass), that is,
// every eigenvalue of M^-1 H above -shift: rigid motions in zero gravity (eigenvalue 0) and
// modes softer than the shift count as neutral, not unstable. Otherwise the direction of most
// negative curvature comes from inverse iteration with a shifted factorisation, and the
// solver (solve_drape) leaves the saddle along it.
#pragma once

#include "sim/bisected_cholesky.h"
#include "sim/cloth_energy.h"

namespace foldsketch {

// Eigenvalues of M^-1 H above -kNeutralCurvature count as stable [1/s^2]. A mode that
// unstable grows by e in 1 / sqrt(0.01) = 10 s, slower than air and the cloth's internal
// friction act. The committed samples' softest modes (bisection on the inertia of H - s M,
// 2026-12-06): flag 1.4e-6 s^-2 (it swings round its pole for nearly nothing), dress 3.8,
// skirt 8.8, box cover 29. Our choice.
constexpr double kNeutralCurvature = 1e-2;

struct StabilityCheck {
  bool stable = true;  // H + kNeutralCurvature M factorised
  // When not stable: the most negative eigenvalue of M^-1 H [1/s^2] as inverse iteration
  // found it (an upper bound), and its mode (3 per free DOF of energy, unit M-norm:
  // mode^T M mode = 1 kg), empty unless the energy curves downwards along it.
  double lowest_eigenvalue = 0;
  VectorXd mode;
  int factorizations = 0;
};

// The stability of drape x: hessian must hold energy's exact Hessian at x (every term exact;
// pattern as energy.pattern()), and cholesky an analysis of that pattern. hessian is left
// shifted by some multiple of the mass. The factorisations are in double precision whatever
// cholesky's precision; it is left as it was.
StabilityCheck check_stability(const ClothEnergy& energy, SparseMatrix& hessian, BisectedCholesky& cholesky);

// The same for a drape on its own: prepares energy at x (self-contact's pattern), evaluates
// the exact Hessian and analyses its pattern.
StabilityCheck check_stability(ClothEnergy& energy, const MatrixX3d& x);

} // namespace foldsketch
