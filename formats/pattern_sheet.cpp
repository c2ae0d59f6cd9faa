#include "formats/pattern_sheet.h"

#include "pattern/piece_layout.h"

namespace foldsketch {
namespace {
constexpr double kMm = 1000.0;
}

PatternSheet pattern_sheet(const std::vector<CuttingPiece>& pieces, const PatternText& text) {
  PatternSheet sheet;
  sheet.pieces = &pieces;
  sheet.names = piece_block_names(pieces);
  sheet.text = text;
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const CuttingPiece& piece : pieces) {
    Eigen::AlignedBox2d box;
    for (const Vector2d& p : piece.cut.outer) box.extend(p);
    boxes.push_back(box);
  }
  boxes.emplace_back(Vector2d::Zero(), Vector2d(PatternSheet::kScaleBoxWidthMm, PatternSheet::kScaleBoxHeightMm) / kMm);
  const SheetLayout layout = shelf_layout(boxes, PatternSheet::kGapMm / kMm);
  sheet.offsets.assign(layout.offsets.begin(), layout.offsets.end() - 1);
  sheet.scale_box = boxes.back().translated(layout.offsets.back());
  sheet.extent = layout.extent;
  return sheet;
}

double PatternSheet::width_mm() const { return extent.sizes().x() * kMm + 2.0 * kMarginMm; }
double PatternSheet::height_mm() const { return extent.sizes().y() * kMm + 2.0 * kMarginMm; }

Vector2d PatternSheet::page(const Vector2d& s) const {
  return {(s.x() - extent.min().x()) * kMm + kMarginMm, (extent.max().y() - s.y()) * kMm + kMarginMm};
}

Vector2d PatternSheet::page(int i, const Vector2d& pattern) const { return page(Vector2d(pattern + offsets[i])); }

std::vector<std::string> PatternSheet::title(int i) const {
  return {names[i], cutting_instruction(*pieces, names, i), ascii_text(text.material)};
}

} // namespace foldsketch
