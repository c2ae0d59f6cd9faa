#include "formats/pattern_sheet.h"

#include "formats/text_numbers.h"
#include "pattern/piece_layout.h"

namespace foldsketch {
namespace {
constexpr double kMm = 1000.0;
constexpr double kTitleHeight = 7.0;  // piece name [mm]
constexpr double kTextHeight = 4.5;   // other lines [mm]
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

Vector2d PatternSheet::scale_box_corner() const { return page(Vector2d(scale_box.min().x(), scale_box.max().y())); }

std::vector<SheetText> PatternSheet::title_block(int i) const {
  const Vector2d start = page(i, (*pieces)[static_cast<size_t>(i)].grain_to) + Vector2d(3.0, kTitleHeight);
  std::vector<SheetText> lines{{start, kTitleHeight, true, names[i]}};
  const Vector2d next = start + Vector2d(0.0, 1.3 * kTitleHeight);
  lines.push_back({next, kTextHeight, false, ascii_text(cutting_instruction(*pieces, names, i))});
  lines.push_back({next + Vector2d(0.0, 1.3 * kTextHeight), kTextHeight, false, ascii_text(text.material)});
  return lines;
}

std::vector<SheetText> PatternSheet::scale_box_text() const {
  std::vector<SheetText> lines;
  Vector2d at = scale_box_corner() + Vector2d(4.0, 9.0);
  for (const std::string& line : {std::string("Scale check: this box is 100 x 50 mm"), "Style: " + text.style_name,
                                  "Size: " + text.size, "Seam allowance: " + format_fixed(text.seam_allowance * kMm, 3) + " mm",
                                  "Date: " + text.creation_date}) {
    lines.push_back({at, kTextHeight, false, ascii_text(line)});
    at.y() += 1.6 * kTextHeight;
  }
  return lines;
}

} // namespace foldsketch
