// In-plane (membrane) energy of one linear triangle: orthotropic St. Venant-Kirchhoff on the
// Green strain of the pattern-to-drape map, with the weft along pattern x and the warp (grain)
// along pattern y. Compression is as stiff as tension (plain StVK). Softer compression (Choi
// & Ko 2002) was measured and removed: at 1 % of the tensile stiffness it lowered the Cusick
// drape coefficient of every fabric (silk 0.41 -> 0.25, cotton 0.28 -> 0.21 with earlier
// presets), and it made cold drapes 3-10 times slower (bench/drape_bench.txt, session 32).
#pragma once

#include "core/types.h"
#include "sim/material.h"

namespace foldsketch {

// Plane-stress orthotropic stiffness [N/m] in the pattern frame, Voigt order (xx, yy, xy):
//   psi = 1/2 C11 E11^2 + C12 E11 E22 + 1/2 C22 E22^2 + 2 C33 E12^2   [J/m^2].
struct MembraneStiffness {
  double c11 = 0, c12 = 0, c22 = 0, c33 = 0;
};

// From uniaxial stiffnesses: C11 = E1/(1 - nu12 nu21), C22 = E2/(1 - nu12 nu21),
// C12 = nu12 E2/(1 - nu12 nu21), nu21 = nu12 E2/E1, C33 = shear (E1 weft, E2 warp).
MembraneStiffness membrane_stiffness(const Material& m);

// Rest data of one triangle: inverse of the 2x2 matrix of pattern edges [X1-X0, X2-X0], and
// the rest area [m^2].
struct MembraneRest {
  Eigen::Matrix2d Dm_inverse;
  double area = 0;
};
MembraneRest membrane_rest(const Vector2d& X0, const Vector2d& X1, const Vector2d& X2);
// Gradients of the triangle's linear shape functions over the pattern [1/m]: column i is
// grad N_i (columns 1, 2 the rows of Dm^-1, column 0 minus their sum), so that the
// deformation gradient is F = sum_i x_i grad N_i^T.
Eigen::Matrix<double, 2, 3> shape_gradients(const MembraneRest& rest);

enum class HessianKind {
  Exact,       // the true Hessian (may be indefinite under compression); for tests
  Projected,   // exact, with negative eigenvalues clamped (only computed where indefinite)
  GaussNewton  // curvature of the strain measure dropped: PSD, exact at zero stress
};

struct Element9 {
  double energy = 0;                  // [J]
  Eigen::Matrix<double, 9, 1> gradient;   // [N], corners 0, 1, 2 with x, y, z each
  Eigen::Matrix<double, 9, 9> hessian;    // [N/m]
};

// Energy, gradient and (when want_hessian) Hessian of the triangle with drape corners x0, x1,
// x2 [m].
Element9 membrane_element(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                          const MembraneStiffness& k, bool want_hessian, HessianKind kind);

// membrane_element's energy alone (line searches need no derivatives).
double membrane_energy(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                       const MembraneStiffness& k);

// Second Piola-Kirchhoff stress [N/m] of the triangle at drape x, in the pattern frame.
Eigen::Matrix2d membrane_stress(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                                const MembraneStiffness& k);

// Green strain (xx, yy, xy) of the triangle in the pattern frame.
Eigen::Vector3d green_strain(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest);

} // namespace foldsketch
