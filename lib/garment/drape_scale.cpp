#include "garment/drape_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "mesh/triangle_geometry.h"

namespace foldsketch {

double median_drape_scale(const Garment& g) {
  const VectorXd drape = double_areas(g.V, g.F), pattern = double_areas(g.P, g.FP).cwiseAbs();
  std::vector<double> scales;
  scales.reserve(static_cast<size_t>(g.F.rows()));
  for (Eigen::Index f = 0; f < g.F.rows(); ++f) {
    const double ratio = drape(f) / pattern(f);
    if (drape(f) > 0 && pattern(f) > 0 && std::isfinite(ratio)) scales.push_back(std::sqrt(ratio));
  }
  if (scales.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto middle = scales.begin() + static_cast<std::ptrdiff_t>(scales.size() / 2);
  std::nth_element(scales.begin(), middle, scales.end());
  return *middle;
}

std::string drape_scale_error(const Garment& g) {
  const double scale = median_drape_scale(g);
  if (!std::isfinite(scale) || (scale <= kLargestPlausibleDrapeScale && scale >= 1.0 / kLargestPlausibleDrapeScale)) return {};
  char text[400];
  std::snprintf(text, sizeof text,
                "the drape is %.3g times the size of its patterns (median over the triangles): the patterns (vt) must be "
                "in metres, as the drape (v) is (patterns in millimetres: scale them by 0.001, in centimetres by 0.01; "
                "texture coordinates in vt are no pattern)",
                scale);
  return text;
}

} // namespace foldsketch
