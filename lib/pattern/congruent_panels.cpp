#include "pattern/congruent_panels.h"

#include <cmath>
#include <limits>
#include <optional>

namespace foldsketch {
namespace {

// Points of a loop relative to their centroid.
std::vector<Vector2d> centred(const Loop2& loop) {
  Vector2d c = Vector2d::Zero();
  for (const Vector2d& p : loop) c += p;
  c /= static_cast<double>(loop.size());
  std::vector<Vector2d> out;
  for (const Vector2d& p : loop) out.push_back(p - c);
  return out;
}

double perimeter(const Loop2& loop) {
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) length += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return length;
}

// Smallest RMS distance between x and y over rotations and cyclic shifts of y's vertex order
// (both centred, same size): for a shift, the best rotation leaves
// sum |x|^2 + sum |y|^2 - 2 sqrt(A^2 + B^2), with A = sum x.y and B = sum x cross y.
double best_rigid_rms(const std::vector<Vector2d>& x, const std::vector<Vector2d>& y) {
  const size_t n = x.size();
  double xx = 0.0, yy = 0.0;
  for (size_t i = 0; i < n; ++i) {
    xx += x[i].squaredNorm();
    yy += y[i].squaredNorm();
  }
  double best = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < n; ++s) {
    double a = 0.0, b = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const Vector2d& p = x[i];
      const Vector2d& q = y[(i + s) % n];
      a += p.dot(q);
      b += p.x() * q.y() - p.y() * q.x();
    }
    best = std::min(best, xx + yy - 2.0 * std::hypot(a, b));
  }
  return std::sqrt(std::max(best, 0.0) / static_cast<double>(n));
}

} // namespace

std::vector<PanelPair> congruent_panels(const std::vector<Loop2>& outlines, double tolerance) {
  const int n = static_cast<int>(outlines.size());
  std::vector<bool> taken(n, false);
  std::vector<PanelPair> pairs;
  for (int a = 0; a < n; ++a) {
    if (taken[a]) continue;
    std::optional<PanelPair> found;
    for (int b = a + 1; b < n && !(found && found->match == PanelMatch::Copy); ++b) {
      if (taken[b] || outlines[a].size() != outlines[b].size() || outlines[a].size() < 3) continue;
      const double scale = perimeter(outlines[a]);
      if (std::abs(perimeter(outlines[b]) - scale) > tolerance * static_cast<double>(outlines[a].size())) continue;
      if (std::abs(std::abs(signed_area(outlines[a])) - std::abs(signed_area(outlines[b]))) > tolerance * scale) continue;
      const std::vector<Vector2d> x = centred(outlines[a]);
      const std::vector<Vector2d> y = centred(outlines[b]);
      const double copy = best_rigid_rms(x, y);
      if (copy <= tolerance) {
        found = PanelPair{a, b, PanelMatch::Copy, copy};
        continue;
      }
      if (found) continue;
      // Mirror: reflect y across its vertical axis and reverse its order to keep it counter-clockwise.
      std::vector<Vector2d> mirrored(y.rbegin(), y.rend());
      for (Vector2d& p : mirrored) p.x() = -p.x();
      const double mirror = best_rigid_rms(x, mirrored);
      if (mirror <= tolerance) found = PanelPair{a, b, PanelMatch::Mirror, mirror};
    }
    if (found) {
      taken[found->a] = taken[found->b] = true;
      pairs.push_back(*found);
    }
  }
  return pairs;
}

} // namespace foldsketch
