#include "mesh/triangle_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace foldsketch {
namespace {
void check_dimensions(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F, const char* who) {
  if (V.cols() != 2 && V.cols() != 3) throw ArgumentError(std::string(who) + ": V must be #V by 2 or 3");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
    throw ArgumentError(std::string(who) + ": face index outside V");
}
} // namespace

VectorXd double_areas(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F) {
  check_dimensions(V, F, "double_areas");
  VectorXd A(F.rows());
  for (int f = 0; f < F.rows(); ++f) {
    if (V.cols() == 2) {
      const Vector2d e1 = V.row(F(f, 1)) - V.row(F(f, 0));
      const Vector2d e2 = V.row(F(f, 2)) - V.row(F(f, 0));
      A(f) = e1.x() * e2.y() - e1.y() * e2.x();
    } else {
      const Vector3d e1 = V.row(F(f, 1)) - V.row(F(f, 0));
      const Vector3d e2 = V.row(F(f, 2)) - V.row(F(f, 0));
      A(f) = e1.cross(e2).norm();
    }
  }
  return A;
}

MatrixX3d edge_lengths(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F) {
  check_dimensions(V, F, "edge_lengths");
  MatrixX3d L(F.rows(), 3);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      L(f, k) = (V.row(F(f, (k + 2) % 3)) - V.row(F(f, (k + 1) % 3))).norm();
  return L;
}

MatrixX3d internal_angles(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F) {
  check_dimensions(V, F, "internal_angles");
  MatrixX3d angles(F.rows(), 3);
  for (int f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVectorXd a = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const Eigen::RowVectorXd b = V.row(F(f, (k + 2) % 3)) - V.row(F(f, k));
      const double na = a.norm(), nb = b.norm();
      if (na == 0.0 || nb == 0.0) {
        angles(f, k) = std::nan("");
        continue;
      }
      // atan2 of |a x b| and a.b is accurate for angles near 0 and pi, unlike acos.
      const double dot = a.dot(b);
      double cross;
      if (V.cols() == 2) cross = std::abs(a(0) * b(1) - a(1) * b(0));
      else cross = Vector3d(a(0), a(1), a(2)).cross(Vector3d(b(0), b(1), b(2))).norm();
      angles(f, k) = std::atan2(cross, dot);
    }
  }
  return angles;
}

VectorXd min_angles(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F) {
  const MatrixX3d angles = internal_angles(V, F);
  VectorXd m(F.rows());
  for (int f = 0; f < F.rows(); ++f) {
    double smallest = angles(f, 0);
    for (int k = 0; k < 3; ++k) {
      if (std::isnan(angles(f, k))) { smallest = 0.0; break; }
      smallest = std::min(smallest, angles(f, k));
    }
    m(f) = smallest;
  }
  return m;
}

TriangleClosestPoint closest_point_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  // Ericson, Real-Time Collision Detection (2005), 5.1.5: Voronoi regions in turn.
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {{1, 0, 0}, 4};
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {{0, 1, 0}, 5};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return {{1 - t, t, 0}, 1};
  }
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {{0, 0, 1}, 6};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return {{1 - t, 0, t}, 3};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {{0, 1 - t, t}, 2};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {  // collapsed triangle: the nearest of its edges
    TriangleClosestPoint best{{1, 0, 0}, 4};
    double best_distance = INFINITY;
    const Vector3d x[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
      const Vector3d s = x[e], d = x[(e + 1) % 3] - s;
      const double t = d.squaredNorm() > 0.0 ? std::clamp((p - s).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      const double dist = (p - s - t * d).norm();
      if (dist < best_distance) {
        best_distance = dist;
        best.weights.setZero();
        best.weights(e) = 1 - t;
        best.weights((e + 1) % 3) += t;
        best.feature = d.squaredNorm() > 0.0 ? e + 1 : 4 + e;  // a zero-length edge is a corner
      }
    }
    return best;
  }
  return {{va / sum, vb / sum, vc / sum}, 0};
}

double point_triangle_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const Vector3d w = closest_point_on_triangle(p, a, b, c).weights;
  return (p - w(0) * a - w(1) * b - w(2) * c).norm();
}

} // namespace foldsketch
