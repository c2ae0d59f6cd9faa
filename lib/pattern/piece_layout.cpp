#include "pattern/piece_layout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace foldsketch {

SheetLayout shelf_layout(const std::vector<Eigen::AlignedBox2d>& boxes, double gap) {
  const size_t n = boxes.size();
  SheetLayout layout;
  layout.offsets.assign(n, Vector2d::Zero());
  double area = 0.0, widest = 0.0;
  for (const auto& b : boxes) {
    area += (b.sizes().x() + gap) * (b.sizes().y() + gap);
    widest = std::max(widest, b.sizes().x());
  }
  const double row_width = std::max(widest, std::sqrt(2.0 * area));
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return boxes[a].sizes().y() > boxes[b].sizes().y(); });
  double x = 0.0, top = 0.0, row_height = 0.0;
  for (size_t i : order) {
    const Eigen::AlignedBox2d& b = boxes[i];
    if (x > 0.0 && x + b.sizes().x() > row_width) {
      top -= row_height + gap;
      x = 0.0;
      row_height = 0.0;
    }
    // The box's top-left corner goes to (x, top).
    layout.offsets[i] = Vector2d(x - b.min().x(), top - b.max().y());
    layout.extent.extend(Vector2d(x, top));
    layout.extent.extend(Vector2d(x + b.sizes().x(), top - b.sizes().y()));
    x += b.sizes().x() + gap;
    row_height = std::max(row_height, b.sizes().y());
  }
  if (layout.extent.isEmpty()) layout.extent.extend(Vector2d::Zero());
  return layout;
}

} // namespace foldsketch
