// PNG preview of the pattern sheet, drawn with OpenCV from the same geometry as the SVG.
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "formats/pattern_sheet.h"

namespace foldsketch {
namespace {

constexpr double kDashMm = 3.0, kGapMm = 2.0;   // the SVG's sew-line dash pattern
// Largest preview side [px]: 16384 keeps a preview of a 10 m sheet under 1 GB of memory.
constexpr double kMaxSide = 16384.0;

const cv::Scalar kCutFill(234, 241, 244), kBlack(0, 0, 0), kGrey(68, 68, 68), kRed(0, 0, 204), kBlue(204, 102, 0);

struct Canvas {
  cv::Mat image;
  double scale;  // px per mm
  cv::Point px(const Vector2d& page_mm) const {
    return {static_cast<int>(std::lround(page_mm.x() * scale)), static_cast<int>(std::lround(page_mm.y() * scale))};
  }
  int thickness(double mm) const { return std::max(1, static_cast<int>(std::lround(mm * scale))); }
};

std::vector<cv::Point> polygon(const Canvas& c, const PatternSheet& sheet, int i, const Loop2& loop) {
  std::vector<cv::Point> points;
  for (const Vector2d& p : loop) points.push_back(c.px(sheet.page(i, p)));
  return points;
}

void dashed_loop(Canvas& c, const PatternSheet& sheet, int i, const Loop2& loop) {
  double phase = 0.0;  // distance along the dash pattern [mm]
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vector2d a = sheet.page(i, loop[k]), b = sheet.page(i, loop[(k + 1) % loop.size()]);
    const double length = (b - a).norm();
    double s = 0.0;
    while (s < length) {
      const double in_period = std::fmod(phase + s, kDashMm + kGapMm);
      const bool on = in_period < kDashMm;
      const double step = std::min(length - s, on ? kDashMm - in_period : kDashMm + kGapMm - in_period);
      if (on) cv::line(c.image, c.px(a + (b - a) * (s / length)), c.px(a + (b - a) * ((s + step) / length)), kGrey,
                       c.thickness(0.3), cv::LINE_AA);
      s += std::max(step, 1e-9);
    }
    phase += length;
  }
}

void text(Canvas& c, const SheetText& t) {
  // Hershey simplex: a font scale of 1 draws capitals about 22 px high; a font's capitals are
  // about 0.7 of its size, as the SVG's font-size.
  cv::putText(c.image, t.text, c.px(t.at), cv::FONT_HERSHEY_SIMPLEX, 0.7 * t.height * c.scale / 22.0, kBlack,
              c.thickness(t.bold ? 0.6 : 0.3), cv::LINE_AA);
}

} // namespace

std::vector<unsigned char> pattern_png(const PatternSheet& sheet, double px_per_mm) {
  if (!(px_per_mm > 0.0)) throw ArgumentError("the PNG resolution must be positive");
  const double side = std::max(sheet.width_mm(), sheet.height_mm()) * px_per_mm;
  const double scale = side > kMaxSide ? px_per_mm * kMaxSide / side : px_per_mm;
  Canvas c{cv::Mat(static_cast<int>(std::ceil(sheet.height_mm() * scale)), static_cast<int>(std::ceil(sheet.width_mm() * scale)),
                   CV_8UC3, cv::Scalar(255, 255, 255)),
           scale};
  const std::vector<CuttingPiece>& pieces = *sheet.pieces;
  for (size_t n = 0; n < pieces.size(); ++n) {
    const int i = static_cast<int>(n);
    const CuttingPiece& piece = pieces[n];
    std::vector<std::vector<cv::Point>> cut;
    for (const Loop2* loop : piece.cut.loops()) cut.push_back(polygon(c, sheet, i, *loop));
    cv::fillPoly(c.image, cut, kCutFill, cv::LINE_AA);
    cv::polylines(c.image, cut, true, kBlack, c.thickness(0.5), cv::LINE_AA);
    if (sheet.text.seam_allowance > 0.0)
      for (const Loop2& sew : piece.sew) dashed_loop(c, sheet, i, sew);
    for (const Notch& notch : piece.notches)
      cv::line(c.image, c.px(sheet.page(i, notch.at)), c.px(sheet.page(i, notch.at + notch.depth * notch.inward)), kRed,
               c.thickness(0.5), cv::LINE_AA);
    const cv::Point g0 = c.px(sheet.page(i, piece.grain_from)), g1 = c.px(sheet.page(i, piece.grain_to));
    const double tip = 6.0 * c.scale / std::max(1.0, std::hypot(g1.x - g0.x, g1.y - g0.y));
    cv::arrowedLine(c.image, g0, g1, kBlue, c.thickness(0.4), cv::LINE_AA, 0, tip);
    cv::arrowedLine(c.image, g1, g0, kBlue, c.thickness(0.4), cv::LINE_AA, 0, tip);
    for (const auto& line : piece.internal_lines)
      for (size_t k = 0; k + 1 < line.size(); ++k)
        cv::line(c.image, c.px(sheet.page(i, line[k])), c.px(sheet.page(i, line[k + 1])), kGrey, c.thickness(0.3), cv::LINE_AA);
    for (const Vector2d& h : piece.drill_holes) cv::circle(c.image, c.px(sheet.page(i, h)), c.thickness(1.0), kBlack, cv::FILLED);
    for (const SheetText& line : sheet.title_block(i)) text(c, line);
  }
  const Vector2d top_left = sheet.scale_box_corner();
  const Vector2d bottom_right = top_left + Vector2d(PatternSheet::kScaleBoxWidthMm, PatternSheet::kScaleBoxHeightMm);
  cv::rectangle(c.image, c.px(top_left), c.px(bottom_right), kBlack, c.thickness(0.5), cv::LINE_AA);
  for (const SheetText& line : sheet.scale_box_text()) text(c, line);
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", c.image, png)) throw ArgumentError("OpenCV could not encode the PNG preview");
  return png;
}

} // namespace foldsketch
