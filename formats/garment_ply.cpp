#include "garment_ply.h"

#include <array>

#include "atomic_file.h"
#include "text_numbers.h"

namespace foldsketch {
namespace {
// Colour-blind-safe qualitative palette (Okabe & Ito 2008), repeated for many panels.
constexpr std::array<std::array<int, 3>, 8> kPalette{{{230, 159, 0}, {86, 180, 233}, {0, 158, 115}, {240, 228, 66},
                                                      {0, 114, 178}, {213, 94, 0}, {204, 121, 167}, {153, 153, 153}}};
} // namespace

std::string garment_ply_text(const Garment& g) {
  const VectorXi drape = pattern_to_drape(g);
  VectorXi panel_of = VectorXi::Constant(g.P.rows(), 0);
  for (int f = 0; f < g.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) panel_of(g.FP(f, k)) = g.face_panel(f);
  std::string text = "ply\nformat ascii 1.0\ncomment foldsketch garment drape [m], coloured by panel\n";
  text += "element vertex " + std::to_string(g.P.rows()) + "\nproperty double x\nproperty double y\nproperty double z\n"
          "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  text += "element face " + std::to_string(g.F.rows()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int p = 0; p < g.P.rows(); ++p) {
    const int v = drape(p) >= 0 ? drape(p) : 0;
    const auto& c = kPalette[static_cast<size_t>(panel_of(p)) % kPalette.size()];
    text += format_double(g.V(v, 0)) + ' ' + format_double(g.V(v, 1)) + ' ' + format_double(g.V(v, 2)) + ' ' +
            std::to_string(c[0]) + ' ' + std::to_string(c[1]) + ' ' + std::to_string(c[2]) + '\n';
  }
  for (int f = 0; f < g.F.rows(); ++f)
    text += "3 " + std::to_string(g.FP(f, 0)) + ' ' + std::to_string(g.FP(f, 1)) + ' ' + std::to_string(g.FP(f, 2)) + '\n';
  return text;
}

void write_garment_ply(const Garment& g, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { out << garment_ply_text(g); });
}

} // namespace foldsketch
