// The printed sheet of cutting patterns: pieces laid out without overlap, a 100 x 50 mm scale
// box, page coordinates in millimetres (x right, y down) with a margin all round. Shared by the
// SVG and PNG writers, and its offsets by the DXF, so all three show the same arrangement.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "formats/dxf_aama.h"
#include "pattern/cutting_pieces.h"

namespace foldsketch {

// One line of text on the sheet: baseline start in page millimetres, font size [mm].
struct SheetText {
  Vector2d at = Vector2d::Zero();
  double height = 0.0;
  bool bold = false;
  std::string text;  // ASCII
};

struct PatternSheet {
  const std::vector<CuttingPiece>* pieces = nullptr;
  std::vector<std::string> names;      // piece_block_names()
  std::vector<Vector2d> offsets;       // pattern -> sheet, per piece [m]
  Eigen::AlignedBox2d scale_box;       // on the sheet [m]
  Eigen::AlignedBox2d extent;          // pieces' cut lines and the scale box on the sheet [m]
  PatternText text;

  static constexpr double kMarginMm = 10.0;
  static constexpr double kScaleBoxWidthMm = 100.0, kScaleBoxHeightMm = 50.0;
  static constexpr double kGapMm = 20.0;  // between pieces

  double width_mm() const;
  double height_mm() const;
  // Page position [mm, y down] of a point of piece i's pattern [m], or of a sheet point.
  Vector2d page(int i, const Vector2d& pattern) const;
  Vector2d page(const Vector2d& sheet) const;
  // Top-left corner of the scale box [page mm].
  Vector2d scale_box_corner() const;
  // Piece i's title block beside the top of its grain line (name, cutting instruction,
  // material), and the lines written in the scale box: the same in the SVG and the PNG.
  std::vector<SheetText> title_block(int i) const;
  std::vector<SheetText> scale_box_text() const;
};

PatternSheet pattern_sheet(const std::vector<CuttingPiece>& pieces, const PatternText& text);

// SVG 1.1, width and height in mm with a matching viewBox (1 user unit = 1 mm): prints at 1:1.
std::string pattern_svg(const PatternSheet& sheet);

// PNG preview of the same drawing at px_per_mm pixels per millimetre (OpenCV).
std::vector<unsigned char> pattern_png(const PatternSheet& sheet, double px_per_mm);

} // namespace foldsketch
