#include "sim/bending.h"

#include <cmath>

#include <Eigen/Geometry>

#include "sim/psd_projection.h"

namespace foldsketch {
namespace {
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Eigen::Matrix3d;

Matrix3d cross_matrix(const Vector3d& v) {
  Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Symmetric "a_i b_j + b_i a_j" placed in the 9x9 of (a, b, c) blocks.
Mat9 sym_outer(const Vec9& u, const Vec9& v) { return u * v.transpose() + v * u.transpose(); }
} // namespace

// With a = x1 - x0 (the edge), b = x2 - x0, c = x3 - x0, the face normals are n1 = a x b and
// n2 = c x a, and
//   n1 . n2 = (a.c)(a.b) - (a.a)(b.c)            (Binet-Cauchy)
//   (n1 x n2) . a / |a| = -det(a, b, c) |a|
// so theta = atan2(y, x) with y = -det(a,b,c) |a| and x = (a.c)(a.b) - |a|^2 (b.c): both are
// polynomials in a, b, c except |a|, and the derivatives follow by the chain rule.
namespace {
// The polynomial parts of the angle (see dihedral_angle), shared with dihedral_theta so that
// both give the same theta to the last bit.
struct AngleParts {
  Vector3d a, b, c;
  double p, q, s, t, L, D, x, y, r2;
  // r2 = |n1|^2 |n2|^2 |a|^2 up to sign conventions: zero when either triangle collapses.
  bool degenerate() const { return !(r2 > 1e-300) || !(L > 0.0); }
};
AngleParts angle_parts(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3) {
  AngleParts k;
  k.a = x1 - x0, k.b = x2 - x0, k.c = x3 - x0;
  k.p = k.a.dot(k.b), k.q = k.a.dot(k.c), k.s = k.a.dot(k.a), k.t = k.b.dot(k.c);
  k.L = std::sqrt(k.s);
  k.D = k.a.dot(k.b.cross(k.c));
  k.x = k.q * k.p - k.s * k.t;
  k.y = -k.D * k.L;
  k.r2 = k.x * k.x + k.y * k.y;
  return k;
}
} // namespace

double dihedral_theta(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, bool* degenerate) {
  const AngleParts k = angle_parts(x0, x1, x2, x3);
  if (degenerate) *degenerate = k.degenerate();
  return k.degenerate() ? 0.0 : std::atan2(k.y, k.x);
}

DihedralAngle dihedral_angle(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3,
                             bool want_hessian) {
  const AngleParts parts = angle_parts(x0, x1, x2, x3);
  const Vector3d &a = parts.a, &b = parts.b, &c = parts.c;
  const double p = parts.p, q = parts.q, s = parts.s, t = parts.t, L = parts.L, D = parts.D, x = parts.x, y = parts.y,
               r2 = parts.r2;
  DihedralAngle out;
  out.gradient.setZero();
  out.hessian.setZero();
  if (parts.degenerate()) {
    out.degenerate = true;
    return out;
  }
  out.theta = std::atan2(y, x);

  Vec9 gD, gL = Vec9::Zero(), gp, gq, gs = Vec9::Zero(), gt;
  gD << b.cross(c), c.cross(a), a.cross(b);
  gL.head<3>() = a / L;
  gp << b, a, Vector3d::Zero();
  gq << c, Vector3d::Zero(), a;
  gs.head<3>() = 2.0 * a;
  gt << Vector3d::Zero(), c, b;
  const Vec9 gx = q * gp + p * gq - t * gs - s * gt;
  const Vec9 gy = -(L * gD + D * gL);
  const double tx = -y / r2, ty = x / r2;
  const Vec9 gtheta = tx * gx + ty * gy;

  // Back to the 12 corner coordinates: a, b, c all move with -x0.
  const auto to_corners = [](const Vec9& g) {
    Eigen::Matrix<double, 12, 1> out12;
    out12.segment<3>(0) = -(g.segment<3>(0) + g.segment<3>(3) + g.segment<3>(6));
    out12.segment<9>(3) = g;
    return out12;
  };
  out.gradient = to_corners(gtheta);
  if (!want_hessian) return out;

  Mat9 hD = Mat9::Zero();
  hD.block<3, 3>(0, 3) = -cross_matrix(c);
  hD.block<3, 3>(0, 6) = cross_matrix(b);
  hD.block<3, 3>(3, 6) = -cross_matrix(a);
  hD.block<3, 3>(3, 0) = hD.block<3, 3>(0, 3).transpose();
  hD.block<3, 3>(6, 0) = hD.block<3, 3>(0, 6).transpose();
  hD.block<3, 3>(6, 3) = hD.block<3, 3>(3, 6).transpose();
  Mat9 hL = Mat9::Zero();
  hL.block<3, 3>(0, 0) = (Matrix3d::Identity() - a * a.transpose() / s) / L;
  // The second derivatives of p = a.b, q = a.c, s = a.a, t = b.c are identity blocks:
  // q hp + p hq - t hs - s ht added block by block.
  Mat9 hx = sym_outer(gp, gq) - sym_outer(gs, gt);
  const Matrix3d I = Matrix3d::Identity();
  hx.block<3, 3>(0, 3) += q * I;
  hx.block<3, 3>(3, 0) += q * I;
  hx.block<3, 3>(0, 6) += p * I;
  hx.block<3, 3>(6, 0) += p * I;
  hx.block<3, 3>(0, 0) -= 2.0 * t * I;
  hx.block<3, 3>(3, 6) -= s * I;
  hx.block<3, 3>(6, 3) -= s * I;
  const Mat9 hy = -(L * hD + sym_outer(gD, gL) + D * hL);
  const double r4 = r2 * r2;
  const double txx = 2 * x * y / r4, tyy = -2 * x * y / r4, txy = (y * y - x * x) / r4;
  const Mat9 htheta = txx * gx * gx.transpose() + tyy * gy * gy.transpose() + txy * sym_outer(gx, gy) + tx * hx + ty * hy;

  // H12 = T^T H9 T with T mapping corners to (a, b, c) = (x1, x2, x3) - x0: the blocks of the
  // last three corners are H9's, and x0's row and column are minus the sums of the others.
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) out.hessian.block<3, 3>(3 * (k + 1), 3 * (l + 1)) = htheta.block<3, 3>(3 * k, 3 * l);
  for (int k = 1; k < 4; ++k) {
    const Matrix3d row_sum = -(out.hessian.block<3, 3>(3 * k, 3) + out.hessian.block<3, 3>(3 * k, 6) + out.hessian.block<3, 3>(3 * k, 9));
    out.hessian.block<3, 3>(3 * k, 0) = row_sum;
    out.hessian.block<3, 3>(0, 3 * k) = row_sum.transpose();
  }
  out.hessian.block<3, 3>(0, 0) = -(out.hessian.block<3, 3>(0, 3) + out.hessian.block<3, 3>(0, 6) + out.hessian.block<3, 3>(0, 9));
  return out;
}

double hinge_stiffness(double bending, double rest_edge_length, double rest_area_1, double rest_area_2) {
  return 0.5 * bending * rest_edge_length * rest_edge_length / (rest_area_1 + rest_area_2);
}

double hinge_energy(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, double stiffness,
                    double rest_angle) {
  bool degenerate = false;
  const double theta = dihedral_theta(x0, x1, x2, x3, &degenerate);
  const double d = degenerate ? 0.0 : theta - rest_angle;
  return stiffness * d * d;
}

Element12 hinge_element(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3, double stiffness,
                        double rest_angle, bool want_hessian, HessianKind kind) {
  const DihedralAngle angle = dihedral_angle(x0, x1, x2, x3, want_hessian && kind != HessianKind::GaussNewton);
  Element12 out;
  const double d = angle.degenerate ? 0.0 : angle.theta - rest_angle;
  out.energy = stiffness * d * d;
  out.gradient = 2.0 * stiffness * d * angle.gradient;
  if (!want_hessian) return out;
  out.hessian = 2.0 * stiffness * angle.gradient * angle.gradient.transpose();
  if (kind == HessianKind::GaussNewton) return out;
  out.hessian += 2.0 * stiffness * d * angle.hessian;
  if (kind == HessianKind::Projected) project_to_psd<12>(out.hessian);
  return out;
}

} // namespace foldsketch
