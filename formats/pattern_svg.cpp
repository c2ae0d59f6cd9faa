#include <cmath>

#include "formats/pattern_sheet.h"
#include "formats/text_numbers.h"

namespace foldsketch {
namespace {

constexpr double kMm = 1000.0;
constexpr double kTitleHeight = 7.0;  // [mm]
constexpr double kTextHeight = 4.5;   // [mm]
constexpr double kArrowLength = 6.0;  // grain-line arrowheads [mm]
constexpr double kArrowHalfWidth = 2.0;

std::string num(double mm) { return format_fixed(mm, 3); }

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

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

std::string text_element(const Vector2d& at, double height, const std::string& s, const char* weight = "normal") {
  return "<text x=\"" + num(at.x()) + "\" y=\"" + num(at.y()) + "\" font-size=\"" + num(height) + "\" font-weight=\"" +
         weight + "\">" + xml_escape(ascii_text(s)) + "</text>\n";
}

} // namespace

std::string pattern_svg(const PatternSheet& sheet) {
  const std::vector<CuttingPiece>& pieces = *sheet.pieces;
  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(sheet.width_mm()) + "mm\" height=\"" +
         num(sheet.height_mm()) + "mm\" viewBox=\"0 0 " + num(sheet.width_mm()) + " " + num(sheet.height_mm()) + "\">\n";
  svg += "<title>" + xml_escape(ascii_text(sheet.text.style_name)) + ": cutting patterns, 1:1, millimetres</title>\n";
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
    std::vector<const Loop2*> cut{&piece.cut.outer};
    for (const Loop2& h : piece.cut.holes) cut.push_back(&h);
    svg += "<path class=\"cut\" d=\"" + loops_path(cut) + "\"/>\n";
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
    // Title block beside the top of the grain line, upright on the page.
    Vector2d at = sheet.page(k, piece.grain_to) + Vector2d(3.0, kTitleHeight);
    const std::vector<std::string> title = sheet.title(k);
    for (size_t t = 0; t < title.size(); ++t) {
      svg += text_element(at, t == 0 ? kTitleHeight : kTextHeight, title[t], t == 0 ? "bold" : "normal");
      at.y() += (t == 0 ? kTitleHeight : kTextHeight) * 1.3;
    }
    svg += "</g>\n";
  }
  // Scale box: measure it on the print; it must be 100 x 50 mm.
  const Vector2d top_left = sheet.page(Vector2d(sheet.scale_box.min().x(), sheet.scale_box.max().y()));
  svg += "<g id=\"scale\">\n<rect id=\"scale-box\" class=\"scale\" x=\"" + num(top_left.x()) + "\" y=\"" + num(top_left.y()) +
         "\" width=\"" + num(PatternSheet::kScaleBoxWidthMm) + "\" height=\"" + num(PatternSheet::kScaleBoxHeightMm) + "\"/>\n";
  Vector2d at = top_left + Vector2d(4.0, 9.0);
  for (const std::string& line : {std::string("Scale check: this box is 100 x 50 mm"), "Style: " + sheet.text.style_name,
                                  "Size: " + sheet.text.size, "Seam allowance: " + num(sheet.text.seam_allowance * kMm) + " mm",
                                  "Date: " + sheet.text.creation_date}) {
    svg += text_element(at, kTextHeight, line);
    at.y() += kTextHeight * 1.6;
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

} // namespace foldsketch
