#include "garment/garment_issues.h"

#include <cmath>

#include "garment/drape_scale.h"
#include "mesh/mesh_edges.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {
namespace {
constexpr size_t kNamedInMessage = 5;

std::string name_items(const std::vector<int>& items) {
  std::string s;
  for (size_t i = 0; i < items.size() && i < kNamedInMessage; ++i) s += (i ? ", " : "") + std::to_string(items[i] + 1);
  if (items.size() > kNamedInMessage) s += ", ...";
  return s;
}
std::string name_edges(const std::vector<std::array<int, 2>>& edges) {
  std::string s;
  for (size_t i = 0; i < edges.size() && i < kNamedInMessage; ++i)
    s += (i ? ", " : "") + std::to_string(edges[i][0] + 1) + "-" + std::to_string(edges[i][1] + 1);
  if (edges.size() > kNamedInMessage) s += ", ...";
  return s;
}
} // namespace

bool GarmentIssues::empty() const {
  return nonfinite_drape_vertices.empty() && nonfinite_pattern_vertices.empty() && degenerate_pattern_faces.empty() &&
         degenerate_drape_faces.empty() && sliver_pattern_faces.empty() && flipped_pattern_faces.empty() &&
         nonmanifold_pattern_edges.empty() && nonmanifold_drape_edges.empty() && misoriented_drape_edges.empty() &&
         drape_scale.empty();
}

std::vector<std::string> GarmentIssues::messages() const {
  std::vector<std::string> out;
  const auto add = [&](size_t n, const std::string& what, const std::string& which) {
    if (n) out.push_back(std::to_string(n) + " " + what + " (" + which + ")");
  };
  add(nonfinite_drape_vertices.size(), "drape vertices with NaN or Inf coordinates: v", name_items(nonfinite_drape_vertices));
  add(nonfinite_pattern_vertices.size(), "pattern vertices with NaN or Inf coordinates: vt", name_items(nonfinite_pattern_vertices));
  add(degenerate_pattern_faces.size(), "degenerate pattern triangles (zero area): f", name_items(degenerate_pattern_faces));
  add(degenerate_drape_faces.size(), "degenerate drape triangles (zero area): f", name_items(degenerate_drape_faces));
  add(sliver_pattern_faces.size(), "sliver pattern triangles: f", name_items(sliver_pattern_faces));
  add(flipped_pattern_faces.size(), "pattern triangles oriented against their panel: f", name_items(flipped_pattern_faces));
  add(nonmanifold_pattern_edges.size(), "non-manifold pattern edges (3+ triangles): vt", name_edges(nonmanifold_pattern_edges));
  add(nonmanifold_drape_edges.size(), "non-manifold drape edges (3+ triangles): v", name_edges(nonmanifold_drape_edges));
  add(misoriented_drape_edges.size(), "drape edges walked the same way by both triangles (inconsistent orientation): v",
      name_edges(misoriented_drape_edges));
  if (!drape_scale.empty()) out.push_back(drape_scale);
  return out;
}

GarmentIssues garment_issues(const Garment& g, const IssueParams& params) {
  GarmentIssues issues;
  issues.drape_scale = drape_scale_error(g);
  for (int v = 0; v < g.V.rows(); ++v)
    if (!g.V.row(v).allFinite()) issues.nonfinite_drape_vertices.push_back(v);
  for (int p = 0; p < g.P.rows(); ++p)
    if (!g.P.row(p).allFinite()) issues.nonfinite_pattern_vertices.push_back(p);

  const VectorXd pattern_area = double_areas(g.P, g.FP);
  const VectorXd drape_area = double_areas(g.V, g.F);
  const MatrixX3d pattern_edges = edge_lengths(g.P, g.FP);
  const MatrixX3d drape_edges = edge_lengths(g.V, g.F);
  const VectorXd pattern_min_angle = min_angles(g.P, g.FP);
  std::vector<double> panel_signed_area(g.panels.size(), 0.0);
  for (int f = 0; f < g.F.rows(); ++f) panel_signed_area[g.face_panel(f)] += pattern_area(f);
  for (int f = 0; f < g.F.rows(); ++f) {
    const double lp = pattern_edges.row(f).maxCoeff(), ld = drape_edges.row(f).maxCoeff();
    if (!(std::abs(pattern_area(f)) > params.degenerate_relative_area * lp * lp)) issues.degenerate_pattern_faces.push_back(f);
    else if (pattern_min_angle(f) < params.sliver_angle) issues.sliver_pattern_faces.push_back(f);
    if (!(drape_area(f) > params.degenerate_relative_area * ld * ld)) issues.degenerate_drape_faces.push_back(f);
    if (pattern_area(f) * panel_signed_area[g.face_panel(f)] < 0.0) issues.flipped_pattern_faces.push_back(f);
  }

  const MeshEdges pe = mesh_edges(g.FP, static_cast<int>(g.P.rows()));
  for (int e = 0; e < pe.E.rows(); ++e)
    if (pe.faces[e].size() > 2) issues.nonmanifold_pattern_edges.push_back({pe.E(e, 0), pe.E(e, 1)});
  const MeshEdges de = mesh_edges(g.F, static_cast<int>(g.V.rows()));
  for (int e = 0; e < de.E.rows(); ++e) {
    const auto& faces = de.faces[e];
    if (faces.size() > 2) issues.nonmanifold_drape_edges.push_back({de.E(e, 0), de.E(e, 1)});
    if (faces.size() != 2) continue;
    // Each triangle walks the edge from one end to the other; consistent neighbours disagree.
    const auto walks_up = [&](int f) {
      for (int k = 0; k < 3; ++k)
        if (g.F(f, k) == de.E(e, 0) && g.F(f, (k + 1) % 3) == de.E(e, 1)) return true;
      return false;
    };
    if (walks_up(faces[0]) == walks_up(faces[1])) issues.misoriented_drape_edges.push_back({de.E(e, 0), de.E(e, 1)});
  }
  return issues;
}

} // namespace foldsketch
