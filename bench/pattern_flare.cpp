#include "pattern_flare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace foldsketch {

Garment flared_patterns(const Garment& g, double flare) {
  if (!(flare >= 0.0)) throw ArgumentError("flared_patterns: the flare must be 0 or more");
  Garment out = g;
  for (int p = 0; p < static_cast<int>(g.panels.size()); ++p) {
    std::vector<int> corners;  // the panel's pattern vertices
    for (int f : panel_faces(g, p))
      for (int k = 0; k < 3; ++k) corners.push_back(g.FP(f, k));
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    if (corners.empty()) continue;
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (int i : corners) {
      x0 = std::min(x0, g.P(i, 0)), x1 = std::max(x1, g.P(i, 0));
      y0 = std::min(y0, g.P(i, 1)), y1 = std::max(y1, g.P(i, 1));
    }
    const double half_band = 0.25 * (x1 - x0), height = y1 - y0;
    if (!(half_band > 0.0) || !(height > 0.0))
      throw ArgumentError("flared_patterns: panel '" + g.panels[p].name + "' has no width or no height");
    const double xc = 0.5 * (x0 + x1), theta = flare * half_band / height;
    for (int i : corners) {
      const double u = g.P(i, 0) - xc, v = g.P(i, 1) - y1;
      const double phi = theta * std::clamp(u / half_band, -1.0, 1.0);
      const double c = std::cos(phi), s = std::sin(phi);
      out.P(i, 0) = xc + c * u - s * v;
      out.P(i, 1) = y1 + s * u + c * v;
    }
  }
  return out;
}

} // namespace foldsketch
