#include "samples/cone_panels.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/error.h"

namespace foldsketch {

Vector3d EllipseRing::point(double phi) const { return {cx + a * std::cos(phi), y, cz - b * std::sin(phi)}; }

std::vector<double> equal_arc_angles(const EllipseRing& ring, int count, double phi0) {
  // Arc length by the trapezoid rule on a fine grid, inverted by linear interpolation.
  constexpr int kSamples = 20000;
  std::vector<double> s(kSamples + 1, 0.0);
  for (int k = 1; k <= kSamples; ++k) {
    const double p0 = phi0 + 2 * std::numbers::pi * (k - 1) / kSamples, p1 = phi0 + 2 * std::numbers::pi * k / kSamples;
    s[k] = s[k - 1] + (ring.point(p1) - ring.point(p0)).norm();
  }
  std::vector<double> phis;
  int k = 0;
  for (int c = 0; c <= count; ++c) {
    const double target = s[kSamples] * c / count;
    while (k < kSamples && s[k + 1] < target) ++k;
    const double t = k < kSamples ? (target - s[k]) / (s[k + 1] - s[k]) : 0.0;
    phis.push_back(phi0 + 2 * std::numbers::pi * (k + t) / kSamples);
  }
  phis.back() = phi0 + 2 * std::numbers::pi;
  return phis;
}

namespace {
// The point at distances da from A and db from B on the right of the directed line A->B.
Vector2d right_of(const Vector2d& A, const Vector2d& B, double da, double db) {
  const double d = (B - A).norm();
  const double along = (da * da - db * db + d * d) / (2 * d);
  const double across = std::sqrt(std::max(0.0, da * da - along * along));
  const Vector2d u = (B - A) / d;
  return A + along * u + across * Vector2d(u.y(), -u.x());
}
} // namespace

GridPanel cone_panel(const std::string& name, const EllipseRing& lower, const EllipseRing& upper,
                     const std::vector<double>& phis, int c0, int c1, int rows) {
  if (c1 <= c0 || rows < 2) throw ArgumentError("cone_panel: empty panel");
  const int columns = c1 - c0 + 1;
  std::vector<Vector3d> B, T;
  for (int c = c0; c <= c1; ++c) {
    B.push_back(lower.point(phis[c]));
    T.push_back(upper.point(phis[c]));
  }
  // Unroll: ruling 0 upright, then each next ruling's ends to the right of the previous.
  std::vector<Vector2d> b(columns), t(columns);
  b[0] = {0, 0};
  t[0] = {0, (T[0] - B[0]).norm()};
  for (int i = 0; i + 1 < columns; ++i) {
    t[i + 1] = right_of(b[i], t[i], (T[i + 1] - B[i]).norm(), (T[i + 1] - T[i]).norm());
    b[i + 1] = right_of(b[i], t[i + 1], (B[i + 1] - B[i]).norm(), (B[i + 1] - T[i + 1]).norm());
  }
  // Turn the middle ruling to +y.
  const int mid = (columns - 1) / 2;
  const Vector2d up = (t[mid] - b[mid]).normalized();
  const Eigen::Rotation2Dd turn(std::atan2(up.x(), up.y()));
  GridPanel p;
  p.name = name;
  p.columns = columns;
  p.rows = rows;
  p.pattern.resize(columns * rows, 2);
  p.drape.resize(columns * rows, 3);
  for (int j = 0; j < rows; ++j) {
    const double s = static_cast<double>(j) / (rows - 1);
    for (int i = 0; i < columns; ++i) {
      p.pattern.row(j * columns + i) = (turn * ((1 - s) * b[i] + s * t[i])).transpose();
      p.drape.row(j * columns + i) = ((1 - s) * B[i] + s * T[i]).transpose();
    }
  }
  return p;
}

} // namespace foldsketch
