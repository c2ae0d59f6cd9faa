#include <cmath>

#include "formats/pattern_sheet.h"
#include "formats/text_numbers.h"
#include "formats/xml_util.h"

namespace foldsketch {
namespace {

constexpr double kMm = 1000.0;
constexpr double kArrowLength = 6.0;  // grain-line arrowheads [mm]
constexpr double kArrowHalfWidth = 2.0;

std::string num(double mm) { return format_fixed(mm, 3); }

// Path data of loops in pattern millimetres.
std::string loops_path(const std::vector<const Loop2*>& loops) {
  std::string d;
  for (const Loop2* loop : loops) {
    for (size_t i = 0; i < loop->size(); ++i) {
      const Vector2d p = (*loop)[i] * kMm;
      d += (i == 0 ? (d.empty() ? "M" : " M") : " L") + num(p.x()) + "," + num(p.y());
    }
    d += " Z";
  }
  return d;
}

std::string segment(const Vector2d& a_mm, const Vector2d& b_mm) {
  return "M" + num(a_mm.x()) + "," + num(a_mm.y()) + " L" + num(b_mm.x()) + "," + num(b_mm.y());
}

// The grain line with an arrowhead at each end.
std::string grain_path(const Vector2d& from, const Vector2d& to) {
  const Vector2d a = from * kMm, b = to * kMm;
  const Vector2d t = (b - a).normalized(), n(-t.y(), t.x());
  std::string d = segment(a, b);
  if (!t.allFinite()) return d;
  for (const auto& [tip, dir] : {std::pair{a, Vector2d(-t)}, std::pair{b, t}}) {
    const Vector2d base = tip - kArrowLength * dir;
    d += " " + segment(base + kArrowHalfWidth * n, tip) + " L" + num((base - kArrowHalfWidth * n).x()) + "," +
         num((base - kArrowHalfWidth * n).y());
  }
  return d;
}

std::string text_element(const SheetText& t) {
  return "<text x=\"" + num(t.at.x()) + "\" y=\"" + num(t.at.y()) + "\" font-size=\"" + num(t.height) + "\" font-weight=\"" +
         (t.bold ? "bold" : "normal") + "\">" + xml_escaped(t.text) + "</text>\n";
}

} // namespace

std::string pattern_svg(const PatternSheet& sheet) {
  const std::vector<CuttingPiece>& pieces = *sheet.pieces;
  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(sheet.width_mm()) + "mm\" height=\"" +
         num(sheet.height_mm()) + "mm\" viewBox=\"0 0 " + num(sheet.width_mm()) + " " + num(sheet.height_mm()) + "\">\n";
  svg += "<title>" + xml_escaped(ascii_text(sheet.text.style_name)) + ": cutting patterns, 1:1, millimetres</title>\n";
  svg += "<style>\n"
         "  .cut { fill: #f4f1ea; fill-rule: evenodd; stroke: #000; stroke-width: 0.5; }\n"
         "  .sew { fill: none; stroke: #444; stroke-width: 0.3; stroke-dasharray: 3 2; }\n"
         "  .notch { fill: none; stroke: #c00; stroke-width: 0.5; }\n"
         "  .grain { fill: none; stroke: #06c; stroke-width: 0.4; }\n"
         "  .internal { fill: none; stroke: #444; stroke-width: 0.3; stroke-dasharray: 1 1; }\n"
         "  .drill { fill: #000; }\n"
         "  .scale { fill: none; stroke: #000; stroke-width: 0.5; }\n"
         "  text { font-family: sans-serif; fill: #000; }\n"
         "</style>\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  for (size_t i = 0; i < pieces.size(); ++i) {
    const CuttingPiece& piece = pieces[i];
    const int k = static_cast<int>(i);
    // Pattern millimetres (y up) to page millimetres (y down).
    const Vector2d origin = sheet.page(k, Vector2d::Zero());
    svg += "<g id=\"piece-" + sheet.names[i] + "\" class=\"piece\">\n";
    svg += "<g transform=\"matrix(1 0 0 -1 " + num(origin.x()) + " " + num(origin.y()) + ")\">\n";
    svg += "<path class=\"cut\" d=\"" + loops_path(piece.cut.loops()) + "\"/>\n";
    if (sheet.text.seam_allowance > 0.0) {
      std::vector<const Loop2*> sew;
      for (const Loop2& s : piece.sew) sew.push_back(&s);
      svg += "<path class=\"sew\" d=\"" + loops_path(sew) + "\"/>\n";
    }
    std::string notches;
    for (const Notch& n : piece.notches)
      notches += (notches.empty() ? "" : " ") + segment(n.at * kMm, (n.at + n.depth * n.inward) * kMm);
    if (!notches.empty()) svg += "<path class=\"notch\" d=\"" + notches + "\"/>\n";
    svg += "<path class=\"grain\" d=\"" + grain_path(piece.grain_from, piece.grain_to) + "\"/>\n";
    for (const auto& line : piece.internal_lines) {
      std::string d;
      for (const Vector2d& p : line) d += (d.empty() ? "M" : " L") + num(p.x() * kMm) + "," + num(p.y() * kMm);
      svg += "<path class=\"internal\" d=\"" + d + "\"/>\n";
    }
    for (const Vector2d& h : piece.drill_holes)
      svg += "<circle class=\"drill\" cx=\"" + num(h.x() * kMm) + "\" cy=\"" + num(h.y() * kMm) + "\" r=\"1\"/>\n";
    svg += "</g>\n";
    for (const SheetText& line : sheet.title_block(k)) svg += text_element(line);  // upright on the page
    svg += "</g>\n";
  }
  // Scale box: measure it on the print; it must be 100 x 50 mm.
  const Vector2d top_left = sheet.scale_box_corner();
  svg += "<g id=\"scale\">\n<rect id=\"scale-box\" class=\"scale\" x=\"" + num(top_left.x()) + "\" y=\"" + num(top_left.y()) +
         "\" width=\"" + num(PatternSheet::kScaleBoxWidthMm) + "\" height=\"" + num(PatternSheet::kScaleBoxHeightMm) + "\"/>\n";
  for (const SheetText& line : sheet.scale_box_text()) svg += text_element(line);
  svg += "</g>\n</svg>\n";
  return svg;
}

} // namespace foldsketch
