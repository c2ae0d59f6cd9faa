#include "garment/coarse_garment.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/error.h"
#include "garment/boundary_runs.h"
#include "garment/drape_transfer.h"
#include "garment/seams.h"
#include "mesh/isotropic_mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {
namespace {

// Positions (into run) of the vertices to keep strictly inside a run of pattern vertices whose
// ends are kept: the vertex nearest to each of k - 1 equally spaced pattern arc lengths,
// k = round(length / spacing), at least min_segments.
std::vector<int> picks_along(const MatrixX2d& P, const std::vector<int>& run, double spacing, int min_segments) {
  const size_t last = run.size() - 1;
  std::vector<double> s(run.size(), 0.0);
  for (size_t i = 1; i <= last; ++i) s[i] = s[i - 1] + (P.row(run[i]) - P.row(run[i - 1])).norm();
  const int k = std::max(min_segments, static_cast<int>(std::lround(s[last] / spacing)));
  std::vector<int> picks;
  size_t i = 0;
  for (int j = 1; j < k; ++j) {
    const double target = s[last] * j / k;
    while (i < last && s[i + 1] < target) ++i;
    const size_t pick = i < last && s[i + 1] - target < target - s[i] ? i + 1 : i;
    if (pick == 0 || pick == last || (!picks.empty() && static_cast<int>(pick) <= picks.back())) continue;
    picks.push_back(static_cast<int>(pick));
  }
  return picks;
}

double loop_area(const MatrixX2d& P, const std::vector<int>& loop) {
  double a = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vector2d p = P.row(loop[i]), q = P.row(loop[(i + 1) % loop.size()]);
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

} // namespace

double spacing_for_triangles(const Garment& g, int triangles) {
  const double area = 0.5 * double_areas(g.P, g.FP).cwiseAbs().sum();
  if (triangles <= 0 || !(area > 0.0)) throw ArgumentError("spacing_for_triangles: no pattern area or no triangles asked for");
  return std::sqrt(4.0 * area / (std::sqrt(3.0) * triangles));
}

Garment coarse_garment(const Garment& g, double spacing, VectorXi* original_vertex) {
  if (!(spacing > 0.0)) throw ArgumentError("coarse_garment: the spacing must be positive");
  if (!g.stitches.empty()) throw ArgumentError("coarse_garment: the garment has explicit stitches, which a coarser mesh cannot carry yet");
  const VectorXi drape = pattern_to_drape(g);
  const std::vector<BoundaryLoop> loops = panel_boundaries(g);
  const std::vector<Seam> sewn = seams(g, loops);
  const std::vector<std::vector<int>> corners = boundary_corners(g, loops, sewn);

  // Kept boundary vertices, as drape vertices: one choice for both sides of a seam.
  std::vector<char> keep(static_cast<size_t>(g.V.rows()), 0);
  const auto kept = [&](int pattern_vertex) { return keep[static_cast<size_t>(drape(pattern_vertex))] != 0; };
  for (size_t l = 0; l < loops.size(); ++l)
    for (int c : corners[l]) keep[static_cast<size_t>(drape(loops[l].vertices[static_cast<size_t>(c)]))] = 1;
  // Picks along the pieces of a run between kept vertices (the run's ends are kept).
  const auto pick_pieces = [&](const std::vector<int>& run, bool closed, int min_segments) {
    if (closed && std::none_of(run.begin(), run.end(), kept)) keep[static_cast<size_t>(drape(run.front()))] = 1;
    // Rotate a closed run to start at a kept vertex, then cut it at every kept vertex.
    std::vector<int> path = run;
    if (closed) {
      std::rotate(path.begin(), std::find_if(path.begin(), path.end(), kept), path.end());
      path.push_back(path.front());
    }
    const int pieces = static_cast<int>(std::count_if(path.begin() + 1, path.end(), kept));
    std::vector<int> piece{path.front()};
    for (size_t i = 1; i < path.size(); ++i) {
      piece.push_back(path[i]);
      if (!kept(path[i]) && i + 1 < path.size()) continue;
      for (int p : picks_along(g.P, piece, spacing, pieces == 1 ? min_segments : 1))
        keep[static_cast<size_t>(drape(piece[static_cast<size_t>(p)]))] = 1;
      piece.assign(1, path[i]);
    }
  };
  // Segments at least on a run between corners: two on a loop with fewer than three corners,
  // so that every loop keeps three vertices or more.
  const auto min_segments = [&](int loop) { return corners[static_cast<size_t>(loop)].size() < 3 ? 2 : 1; };
  // Seams first, along side a; their edges are then done.
  std::unordered_set<std::uint64_t> seam_edges;
  for (const Seam& s : sewn) {
    pick_pieces(s.a.vertices, s.closed, s.closed ? 3 : min_segments(s.a.loop));
    const auto& v = s.a.vertices;
    for (size_t i = 0; i + 1 < v.size() + (s.closed ? 1 : 0); ++i)
      seam_edges.insert(undirected_edge_key(drape(v[i]), drape(v[(i + 1) % v.size()])));
  }
  // Then every run between corners that is not all seam.
  for (const BoundaryRun& run : boundary_runs(loops, corners)) {
    bool all_sewn = true;
    const size_t edges = run.closed ? run.vertices.size() : run.vertices.size() - 1;
    for (size_t i = 0; i < edges && all_sewn; ++i)
      all_sewn = seam_edges.count(undirected_edge_key(drape(run.vertices[i]), drape(run.vertices[(i + 1) % run.vertices.size()]))) > 0;
    if (!all_sewn) pick_pieces(run.vertices, run.closed, run.closed ? 3 : min_segments(run.loop));
  }

  // Remesh each panel inside its kept outline; kept vertices stay one drape vertex across panels.
  Garment out;
  out.panels = g.panels;
  std::vector<Eigen::RowVector2d> P;
  std::vector<Eigen::RowVector3i> F, FP;
  std::vector<int> face_panel;
  std::unordered_map<int, int> coarse_of;  // original drape vertex -> coarse drape vertex
  int drape_count = 0;
  for (int p = 0; p < static_cast<int>(g.panels.size()); ++p) {
    std::vector<std::vector<int>> outlines;  // kept pattern vertices of each of the panel's loops
    for (const BoundaryLoop& loop : loops) {
      if (loop.panel != p) continue;
      std::vector<int>& o = outlines.emplace_back();
      for (int v : loop.vertices)
        if (kept(v)) o.push_back(v);
      if (o.size() < 3)
        throw ArgumentError("coarse_garment: panel '" + g.panels[static_cast<size_t>(p)].name + "' keeps fewer than three outline vertices at spacing " +
                            std::to_string(spacing) + " m");
    }
    if (outlines.empty()) continue;
    // The outer outline encloses the most area; the rest are holes.
    size_t outer = 0;
    for (size_t k = 1; k < outlines.size(); ++k)
      if (std::abs(loop_area(g.P, outlines[k])) > std::abs(loop_area(g.P, outlines[outer]))) outer = k;
    std::swap(outlines[0], outlines[outer]);
    if (loop_area(g.P, outlines[0]) < 0.0) std::reverse(outlines[0].begin(), outlines[0].end());
    const auto polygon = [&](const std::vector<int>& o) {
      MatrixX2d M(static_cast<long>(o.size()), 2);
      for (size_t k = 0; k < o.size(); ++k) M.row(static_cast<long>(k)) = g.P.row(o[k]);
      return M;
    };
    std::vector<MatrixX2d> holes;
    for (size_t k = 1; k < outlines.size(); ++k) holes.push_back(polygon(outlines[k]));
    const PlanarMesh planar = isotropic_mesh(polygon(outlines[0]), spacing, {}, holes);

    // Drape vertex of each of the planar mesh's points: the outlines' come first, in order.
    std::vector<int> boundary;
    for (const auto& o : outlines) boundary.insert(boundary.end(), o.begin(), o.end());
    const int offset = static_cast<int>(P.size());
    std::vector<int> drape_of(static_cast<size_t>(planar.P.rows()));
    for (int v = 0; v < planar.P.rows(); ++v) {
      P.push_back(planar.P.row(v));
      if (v < static_cast<int>(boundary.size())) {
        const auto [it, added] = coarse_of.try_emplace(drape(boundary[static_cast<size_t>(v)]), drape_count);
        if (added) ++drape_count;
        drape_of[static_cast<size_t>(v)] = it->second;
      } else {
        drape_of[static_cast<size_t>(v)] = drape_count++;
      }
    }
    for (int f = 0; f < planar.F.rows(); ++f) {
      FP.emplace_back(offset + planar.F(f, 0), offset + planar.F(f, 1), offset + planar.F(f, 2));
      F.emplace_back(drape_of[static_cast<size_t>(planar.F(f, 0))], drape_of[static_cast<size_t>(planar.F(f, 1))],
                     drape_of[static_cast<size_t>(planar.F(f, 2))]);
      face_panel.push_back(p);
    }
  }
  out.P.resize(static_cast<long>(P.size()), 2);
  for (size_t i = 0; i < P.size(); ++i) out.P.row(static_cast<long>(i)) = P[i];
  out.F.resize(static_cast<long>(F.size()), 3);
  out.FP.resize(static_cast<long>(FP.size()), 3);
  out.face_panel.resize(static_cast<long>(face_panel.size()));
  for (size_t f = 0; f < F.size(); ++f) {
    out.F.row(static_cast<long>(f)) = F[f];
    out.FP.row(static_cast<long>(f)) = FP[f];
    out.face_panel(static_cast<long>(f)) = face_panel[f];
  }
  out.V = MatrixX3d::Zero(drape_count, 3);  // sized for transfer_drape, which fills it
  out.V = transfer_drape(g, g.V, out);
  if (original_vertex) {
    *original_vertex = VectorXi::Constant(drape_count, -1);
    for (const auto& [original, coarse] : coarse_of) (*original_vertex)(coarse) = original;
  }
  return out;
}

} // namespace foldsketch
