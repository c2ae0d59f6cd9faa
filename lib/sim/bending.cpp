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

namespace {
// theta's first derivatives through x and y (see above), in the 9 coordinates (a, b, c).
struct AngleGradient {
  Vec9 gx, gy;
  double tx = 0, ty = 0;    // d theta / dx, d theta / dy
  double txx = 0, txy = 0;  // second derivatives (d2 theta / dy2 = -txx)
  Vec9 gradient() const { return tx * gx + ty * gy; }
  // theta's Hessian in (x, y).
  Eigen::Matrix2d second() const { return (Eigen::Matrix2d() << txx, txy, txy, -txx).finished(); }
};
AngleGradient angle_gradient(const AngleParts& k) {
  const Vector3d &a = k.a, &b = k.b, &c = k.c;
  AngleGradient out;
  // x = q p - s t and y = -D L with p = a.b, q = a.c, s = a.a, t = b.c, D = det(a, b, c),
  // L = |a|: dp = (b, a, 0), dq = (c, 0, a), ds = (2a, 0, 0), dt = (0, c, b),
  // dD = (b x c, c x a, a x b), dL = (a / L, 0, 0).
  out.gx << k.q * b + k.p * c - 2.0 * k.t * a, k.q * a - k.s * c, k.p * a - k.s * b;
  out.gy << -(k.L * b.cross(c) + k.D * a / k.L), -k.L * c.cross(a), -k.L * a.cross(b);
  out.tx = -k.y / k.r2;
  out.ty = k.x / k.r2;
  const double r4 = k.r2 * k.r2;
  out.txx = 2.0 * k.x * k.y / r4;
  out.txy = (k.y * k.y - k.x * k.x) / r4;
  return out;
}

// U Q U^T + w (tx hx + ty hy), U = [gx gy], block by block: the second derivatives of theta
// (Q = [txx txy; txy -txx], w = 1), or of f(theta) through them (hinge_element).
// hx and hy, the Hessians of x and y, by 3x3 blocks of (a, b, c):
//   hx = [bc^T + cb^T - 2t I,  ca^T - 2ac^T + q I,  ba^T - 2ab^T + p I;
//         .,                   0,                   aa^T - s I;
//         .,                   .,                   0]
//   hy = -[gD0 l^T + l gD0^T + D (I - aa^T/s)/L,  -L[c]x + l gD1^T,  L[b]x + l gD2^T;
//          .,                                     0,                 -L[a]x;
//          .,                                     .,                 0]
// with l = a / L and gD = (b x c, c x a, a x b) (the lower blocks are the transposes).
Mat9 angle_hessian(const AngleParts& k, const AngleGradient& g, const Eigen::Matrix2d& Q, double w) {
  const Vector3d &a = k.a, &b = k.b, &c = k.c;
  Eigen::Matrix<double, 9, 2> U;
  U.col(0) = g.gx;
  U.col(1) = g.gy;
  const Eigen::Matrix<double, 9, 2> UQ = U * Q;
  Mat9 H;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) H.block<3, 3>(3 * i, 3 * j).noalias() = UQ.block<3, 2>(3 * i, 0) * U.block<3, 2>(3 * j, 0).transpose();
  if (w != 0.0) {
    const double wx = w * g.tx, wy = w * g.ty;
    const Matrix3d I = Matrix3d::Identity();
    const Vector3d l = a / k.L;
    const Vector3d d0 = b.cross(c), d1 = c.cross(a), d2 = a.cross(b);
    H.block<3, 3>(0, 0) += wx * (b * c.transpose() + c * b.transpose() - 2.0 * k.t * I) -
                           wy * (d0 * l.transpose() + l * d0.transpose() + (k.D / k.L) * (I - l * l.transpose()));
    H.block<3, 3>(0, 3) += wx * (c * a.transpose() - 2.0 * a * c.transpose() + k.q * I) - wy * (-k.L * cross_matrix(c) + l * d1.transpose());
    H.block<3, 3>(0, 6) += wx * (b * a.transpose() - 2.0 * a * b.transpose() + k.p * I) - wy * (k.L * cross_matrix(b) + l * d2.transpose());
    H.block<3, 3>(3, 6) += wx * (a * a.transpose() - k.s * I) + wy * k.L * cross_matrix(a);
  }
  // The blocks below the diagonal mirror those above; the diagonal ones are made symmetric to
  // the last bit.
  for (int i = 0; i < 3; ++i) {
    H.block<3, 3>(3 * i, 3 * i) = (0.5 * (H.block<3, 3>(3 * i, 3 * i) + H.block<3, 3>(3 * i, 3 * i).transpose())).eval();
    for (int j = i + 1; j < 3; ++j) H.block<3, 3>(3 * j, 3 * i) = H.block<3, 3>(3 * i, 3 * j).transpose();
  }
  return H;
}

// Back to the 12 corner coordinates: a, b, c all move with -x0.
Eigen::Matrix<double, 12, 1> to_corners(const Vec9& g) {
  Eigen::Matrix<double, 12, 1> out;
  out.segment<3>(0) = -(g.segment<3>(0) + g.segment<3>(3) + g.segment<3>(6));
  out.segment<9>(3) = g;
  return out;
}
// H12 = T^T H9 T with T mapping corners to (a, b, c) = (x1, x2, x3) - x0: the blocks of the
// last three corners are H9's, and x0's row and column are minus the sums of the others.
Eigen::Matrix<double, 12, 12> to_corners(const Mat9& h) {
  Eigen::Matrix<double, 12, 12> out;
  out.block<9, 9>(3, 3) = h;
  for (int k = 1; k < 4; ++k) {
    const Matrix3d row_sum = -(h.block<3, 3>(3 * (k - 1), 0) + h.block<3, 3>(3 * (k - 1), 3) + h.block<3, 3>(3 * (k - 1), 6));
    out.block<3, 3>(3 * k, 0) = row_sum;
    out.block<3, 3>(0, 3 * k) = row_sum.transpose();
  }
  out.block<3, 3>(0, 0) = -(out.block<3, 3>(0, 3) + out.block<3, 3>(0, 6) + out.block<3, 3>(0, 9));
  return out;
}
} // namespace

DihedralAngle dihedral_angle(const Vector3d& x0, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3,
                             bool want_hessian) {
  const AngleParts parts = angle_parts(x0, x1, x2, x3);
  DihedralAngle out;
  if (parts.degenerate()) {
    out.gradient.setZero();
    out.hessian.setZero();
    out.degenerate = true;
    return out;
  }
  out.theta = std::atan2(parts.y, parts.x);
  const AngleGradient g = angle_gradient(parts);
  out.gradient = to_corners(g.gradient());
  if (want_hessian) out.hessian = to_corners(angle_hessian(parts, g, g.second(), 1.0));
  else out.hessian.setZero();
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
  const AngleParts parts = angle_parts(x0, x1, x2, x3);
  Element12 out;
  if (parts.degenerate()) {  // theta undefined: no energy, no force, no stiffness
    out.gradient.setZero();
    out.hessian.setZero();
    return out;
  }
  const double d = std::atan2(parts.y, parts.x) - rest_angle;
  out.energy = stiffness * d * d;
  const AngleGradient g = angle_gradient(parts);
  out.gradient = to_corners(Vec9(2.0 * stiffness * d * g.gradient()));
  if (!want_hessian) return out;
  // d2E = 2k (dtheta dtheta^T + d d2theta), and dtheta = U m with m = (tx, ty): the rank-two
  // part is U Q U^T with Q = 2k (m m^T + d [txx txy; txy -txx]); Gauss-Newton keeps m m^T.
  const Eigen::Vector2d m(g.tx, g.ty);
  Eigen::Matrix2d Q = m * m.transpose();
  const double w = kind == HessianKind::GaussNewton ? 0.0 : d;
  Q += w * g.second();
  out.hessian = to_corners(angle_hessian(parts, g, 2.0 * stiffness * Q, 2.0 * stiffness * w));
  if (kind == HessianKind::Projected) project_to_psd<12>(out.hessian);
  return out;
}

} // namespace foldsketch
