// Bending energy of one hinge (two triangles sharing an edge): Discrete Shells (Grinspun et
// al. 2003), E = k (theta - theta0)^2 with theta the dihedral angle.
//
// Calibration: summed over a mesh, 3 |e|^2 / (A1 + A2) theta^2 tends to 3 kappa^2 A on a
// cylinder of curvature kappa, and the plate energy is (D/2) kappa^2 A, so
//   k = (D / 6) * 3 |e|^2 / (A1 + A2) = (D / 2) |e|^2 / (A1 + A2)
// with rest edge length |e| and rest areas A1, A2 (design notes, section 5).
#pragma once

#include "core/types.h"
#include "sim/membrane.h"

namespace foldsketch {

// Hinge corners: x0, x1 the shared edge; x2 the third corner of the triangle walking
// x0 -> x1, x3 the third corner of the other triangle. theta = 0 when flat, signed.
struct DihedralAngle {
  double theta = 0;
  Eigen::Matrix<double, 12, 1> gradient;
  Eigen::Matrix<double, 12, 12> hessian;
  bool degenerate = false;  // a collapsed triangle: theta undefined, derivatives zero
};

DihedralAngle dihedral_angle(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3,
                             bool want_hessian);
// theta alone (0 and *degenerate set when a triangle has collapsed), equal to dihedral_angle's.
double dihedral_theta(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, bool* degenerate = nullptr);

// k = (D/2) |e|^2 / (A1 + A2) from rest edge length [m], rest areas [m^2] and D [N m].
double hinge_stiffness(double bending, double rest_edge_length, double rest_area_1, double rest_area_2);

struct Element12 {
  double energy = 0;
  Eigen::Matrix<double, 12, 1> gradient;
  Eigen::Matrix<double, 12, 12> hessian;
};

Element12 hinge_element(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, double stiffness,
                        double rest_angle, bool want_hessian, HessianKind kind);
// hinge_element's energy alone (line searches need no derivatives).
double hinge_energy(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, double stiffness,
                    double rest_angle);

} // namespace foldsketch
