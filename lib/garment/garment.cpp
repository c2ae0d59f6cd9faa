#include "garment/garment.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace foldsketch {
namespace {
template <typename M>
bool same_bits(const M& a, const M& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::equal(a.data(), a.data() + a.size(), b.data(),
                    [](double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); });
}
template <typename M>
bool same_ints(const M& a, const M& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a.size() == 0 || a == b);
}
} // namespace

bool operator==(const Garment& a, const Garment& b) {
  return same_bits(a.V, b.V) && same_bits(a.P, b.P) && same_ints(a.F, b.F) && same_ints(a.FP, b.FP) &&
         same_ints(a.face_panel, b.face_panel) && a.panels == b.panels && a.stitches == b.stitches;
}

VectorXi pattern_to_drape(const Garment& g) {
  VectorXi map = VectorXi::Constant(g.P.rows(), -1);
  for (int f = 0; f < g.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) map(g.FP(f, k)) = g.F(f, k);
  return map;
}

std::vector<int> panel_faces(const Garment& g, int p) {
  std::vector<int> faces;
  for (int f = 0; f < g.face_panel.size(); ++f)
    if (g.face_panel(f) == p) faces.push_back(f);
  return faces;
}

MatrixX3i panel_pattern_faces(const Garment& g, int p) {
  const std::vector<int> faces = panel_faces(g, p);
  MatrixX3i FP(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t i = 0; i < faces.size(); ++i) FP.row(static_cast<Eigen::Index>(i)) = g.FP.row(faces[i]);
  return FP;
}

std::string garment_structure_error(const Garment& g) {
  const auto nF = g.F.rows();
  if (g.FP.rows() != nF || g.face_panel.size() != nF) return "F, FP and face_panel differ in length";
  if (nF == 0) return "the garment has no triangles";
  if (g.F.minCoeff() < 0 || g.F.maxCoeff() >= g.V.rows()) return "a triangle names a drape vertex that does not exist";
  if (g.FP.minCoeff() < 0 || g.FP.maxCoeff() >= g.P.rows()) return "a triangle names a pattern vertex that does not exist";
  const int nPanels = static_cast<int>(g.panels.size());
  if (g.face_panel.minCoeff() < 0 || g.face_panel.maxCoeff() >= nPanels) return "a triangle names a panel that does not exist";
  for (int f = 1; f < nF; ++f)
    if (g.face_panel(f) < g.face_panel(f - 1)) return "triangles are not sorted by panel";
  std::vector<int> drape_of(static_cast<size_t>(g.P.rows()), -1), panel_of(static_cast<size_t>(g.P.rows()), -1);
  for (int f = 0; f < nF; ++f)
    for (int k = 0; k < 3; ++k) {
      const int p = g.FP(f, k);
      if (drape_of[p] >= 0 && drape_of[p] != g.F(f, k))
        return "pattern vertex " + std::to_string(p + 1) + " is used with drape vertices " +
               std::to_string(drape_of[p] + 1) + " and " + std::to_string(g.F(f, k) + 1);
      if (panel_of[p] >= 0 && panel_of[p] != g.face_panel(f))
        return "pattern vertex " + std::to_string(p + 1) + " is used by panels '" + g.panels[panel_of[p]].name +
               "' and '" + g.panels[g.face_panel(f)].name + "'";
      drape_of[p] = g.F(f, k);
      panel_of[p] = g.face_panel(f);
    }
  std::vector<bool> used(static_cast<size_t>(nPanels), false);
  for (int f = 0; f < nF; ++f) used[g.face_panel(f)] = true;
  for (int p = 0; p < nPanels; ++p)
    if (!used[p]) return "panel '" + g.panels[p].name + "' has no triangles";
  const auto bad_point = [&](const StitchPoint& s) {
    return s.v0 < 0 || s.v0 >= g.V.rows() || s.v1 >= g.V.rows() || s.v1 < -1 || !(s.t >= 0.0 && s.t <= 1.0);
  };
  for (size_t i = 0; i < g.stitches.size(); ++i)
    if (bad_point(g.stitches[i].a) || bad_point(g.stitches[i].b))
      return "stitch " + std::to_string(i + 1) + " names a drape vertex that does not exist or has t outside [0, 1]";
  return {};
}

} // namespace foldsketch
