#include "metrics/garment_summary.h"

#include <algorithm>
#include <cmath>

#include "garment/boundary_runs.h"
#include "garment/deformation.h"
#include "garment/seams.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {

GarmentSummary garment_summary(const Garment& g) {
  GarmentSummary s;
  s.triangles = static_cast<int>(g.F.rows());
  s.drape_vertices = static_cast<int>(g.V.rows());
  s.pattern_vertices = static_cast<int>(g.P.rows());
  s.stitches = static_cast<int>(g.stitches.size());
  s.issues = garment_issues(g);

  const VectorXd pattern_area = double_areas(g.P, g.FP).cwiseAbs() / 2;
  const VectorXd drape_area = double_areas(g.V, g.F) / 2;
  const VectorXd min_angle = min_angles(g.P, g.FP);
  s.min_angle = min_angle.minCoeff();
  s.mean_min_angle = min_angle.mean();
  const MatrixX2d stretch = principal_stretches(g);
  s.min_stretch = stretch.col(1).minCoeff();
  s.max_stretch = stretch.col(0).maxCoeff();
  for (int v = 0; v < g.V.rows(); ++v) s.drape_box.extend(g.V.row(v).transpose());

  const std::vector<BoundaryLoop> loops = panel_boundaries(g);
  const std::vector<Seam> all_seams = seams(g, loops);
  const std::vector<BoundaryRun> runs = boundary_runs(loops, boundary_corners(g, loops, all_seams));

  for (int p = 0; p < static_cast<int>(g.panels.size()); ++p) {
    PanelSummary ps;
    ps.name = g.panels[p].name;
    ps.min_angle = 4.0;  // above any angle
    std::vector<bool> used(static_cast<size_t>(g.P.rows()), false);
    for (int f = 0; f < g.F.rows(); ++f) {
      if (g.face_panel(f) != p) continue;
      ++ps.triangles;
      ps.area += pattern_area(f);
      ps.drape_area += drape_area(f);
      ps.min_angle = std::min(ps.min_angle, min_angle(f));
      for (int k = 0; k < 3; ++k) used[g.FP(f, k)] = true;
    }
    ps.vertices = static_cast<int>(std::count(used.begin(), used.end(), true));
    for (const BoundaryLoop& l : loops) ps.loops += l.panel == p;
    for (const BoundaryRun& r : runs)
      if (loops[r.loop].panel == p)
        ps.runs.push_back({pattern_length(g.P, r.vertices, r.closed), static_cast<int>(r.vertices.size()), r.closed});
    s.panels.push_back(std::move(ps));
  }
  for (const Seam& seam : all_seams) {
    s.seams.push_back({seam.a.panel, seam.b.panel, static_cast<int>(seam.a.vertices.size()), seam.closed,
                       pattern_length(g.P, seam.a.vertices, seam.closed), pattern_length(g.P, seam.b.vertices, seam.closed),
                       drape_length(g, seam.a.vertices, seam.closed)});
  }
  return s;
}

} // namespace foldsketch
