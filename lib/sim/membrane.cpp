#include "sim/membrane.h"

#include <cmath>

#include <Eigen/LU>

#include "sim/psd_projection.h"

namespace foldsketch {

MembraneStiffness membrane_stiffness(const Material& m) {
  const double e1 = m.stretch_weft, e2 = m.stretch_warp, nu12 = m.poisson;
  const double nu21 = nu12 * e2 / e1;
  const double denom = 1.0 - nu12 * nu21;
  return {e1 / denom, nu12 * e2 / denom, e2 / denom, m.shear};
}

MembraneRest membrane_rest(const Vector2d& X0, const Vector2d& X1, const Vector2d& X2) {
  Eigen::Matrix2d Dm;
  Dm.col(0) = X1 - X0;
  Dm.col(1) = X2 - X0;
  const double det = Dm.determinant();
  MembraneRest r;
  r.area = 0.5 * std::abs(det);
  r.Dm_inverse = (Eigen::Matrix2d() << Dm(1, 1), -Dm(0, 1), -Dm(1, 0), Dm(0, 0)).finished() / det;
  return r;
}

Eigen::Matrix<double, 2, 3> shape_gradients(const MembraneRest& rest) {
  Eigen::Matrix<double, 2, 3> b;
  b.col(1) = rest.Dm_inverse.row(0).transpose();
  b.col(2) = rest.Dm_inverse.row(1).transpose();
  b.col(0) = -b.col(1) - b.col(2);
  return b;
}

namespace {
using Matrix32 = Eigen::Matrix<double, 3, 2>;

Eigen::Matrix2d stress(const Eigen::Matrix2d& E, const MembraneStiffness& k) {
  Eigen::Matrix2d S;
  S(0, 0) = k.c11 * E(0, 0) + k.c12 * E(1, 1);
  S(1, 1) = k.c12 * E(0, 0) + k.c22 * E(1, 1);
  S(0, 1) = S(1, 0) = 2.0 * k.c33 * E(0, 1);
  return S;
}

Matrix32 deformation(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest) {
  Matrix32 Ds;
  Ds.col(0) = x1 - x0;
  Ds.col(1) = x2 - x0;
  return Ds * rest.Dm_inverse;
}

// Green strain E = (F^T F - I) / 2 of deformation gradient F.
Eigen::Matrix2d strain_of(const Matrix32& F) { return 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity()); }
} // namespace

Eigen::Vector3d green_strain(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest) {
  const Eigen::Matrix2d E = strain_of(deformation(x0, x1, x2, rest));
  return {E(0, 0), E(1, 1), E(0, 1)};
}

namespace {
// W = A (c11/2 E11^2 + c12 E11 E22 + c22/2 E22^2 + 2 c33 E12^2).
double strain_energy(const Eigen::Matrix2d& E, const MembraneStiffness& k, double area) {
  return area * (0.5 * k.c11 * E(0, 0) * E(0, 0) + k.c12 * E(0, 0) * E(1, 1) + 0.5 * k.c22 * E(1, 1) * E(1, 1) +
                 2.0 * k.c33 * E(0, 1) * E(0, 1));
}
} // namespace

double membrane_energy(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                       const MembraneStiffness& stiffness) {
  const Eigen::Matrix2d E = strain_of(deformation(x0, x1, x2, rest));
  return strain_energy(E, stiffness, rest.area);
}

Element9 membrane_element(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                          const MembraneStiffness& stiffness, bool want_hessian, HessianKind kind) {
  const Matrix32 F = deformation(x0, x1, x2, rest);
  const Eigen::Matrix2d E = strain_of(F);
  const MembraneStiffness& k = stiffness;
  const Eigen::Matrix2d S = stress(E, k);
  Element9 out;
  out.energy = strain_energy(E, k, rest.area);
  // dW = A (F S) : dF and dF = dDs Dm^-1, so dW/dDs = A F S Dm^-T.
  const Matrix32 G = rest.area * F * S * rest.Dm_inverse.transpose();
  out.gradient.segment<3>(3) = G.col(0);
  out.gradient.segment<3>(6) = G.col(1);
  out.gradient.segment<3>(0) = -G.col(0) - G.col(1);
  if (!want_hessian) return out;

  // Block by block, with F = sum_i x_i b_i^T (b_1, b_2 the rows of Dm^-1, b_0 = -b_1 - b_2):
  //   d2W/dx_i dx_j = A [ (b_i^T S b_j) I + R_i^T C R_j ],
  // the geometric term (dropped for Gauss-Newton) and the material term, where R_i is the
  // 3x3 derivative of the Voigt strain (E11, E22, E12) by x_i, rows b_i0 f1, b_i1 f2,
  // (b_i0 f2 + b_i1 f1)/2 (f1, f2 the columns of F), and C = [c11 c12 0; c12 c22 0; 0 0 4 c33]
  // the energy's second derivative in those strains.
  const bool stress_psd = S.trace() >= 0.0 && S.determinant() >= 0.0;
  const bool geometric = kind != HessianKind::GaussNewton;
  const Eigen::Matrix<double, 2, 3> b = shape_gradients(rest);
  const Vector3d f1 = F.col(0), f2 = F.col(1);
  Eigen::Matrix3d R[3], CR[3];
  for (int i = 0; i < 3; ++i) {
    R[i].row(0) = b(0, i) * f1.transpose();
    R[i].row(1) = b(1, i) * f2.transpose();
    R[i].row(2) = 0.5 * (b(0, i) * f2 + b(1, i) * f1).transpose();
    CR[i].row(0) = rest.area * (k.c11 * R[i].row(0) + k.c12 * R[i].row(1));
    CR[i].row(1) = rest.area * (k.c12 * R[i].row(0) + k.c22 * R[i].row(1));
    CR[i].row(2) = rest.area * 4.0 * k.c33 * R[i].row(2);
  }
  const Eigen::Matrix3d SB = geometric ? Eigen::Matrix3d(rest.area * b.transpose() * S * b) : Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      Eigen::Matrix3d block = R[i].transpose() * CR[j];
      if (j == i) block = (0.5 * (block + block.transpose())).eval();  // symmetric to the last bit
      block.diagonal().array() += SB(i, j);
      out.hessian.block<3, 3>(3 * i, 3 * j) = block;
      if (j != i) out.hessian.block<3, 3>(3 * j, 3 * i) = block.transpose();
    }
  // With S positive semi-definite the geometric term is PSD too, so only compressed
  // triangles need the (costlier) eigen-decomposition.
  if (kind == HessianKind::Projected && !stress_psd) project_to_psd<9>(out.hessian);
  return out;
}

Eigen::Matrix2d membrane_stress(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const MembraneRest& rest,
                                const MembraneStiffness& k) {
  const Eigen::Matrix2d E = strain_of(deformation(x0, x1, x2, rest));
  return stress(E, k);
}

} // namespace foldsketch
