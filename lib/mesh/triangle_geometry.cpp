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

} // namespace foldsketch
