#include "pattern/cutting_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace foldsketch {
namespace {

Loop2 loop_points(const MatrixX2d& P, const std::vector<int>& vertices) {
  Loop2 loop;
  for (int v : vertices) loop.emplace_back(P.row(v).transpose());
  return loop;
}

// Smallest t > 0 at which p + t * dir meets one of the loops' edges; infinity if none.
double ray_hit(const Vector2d& p, const Vector2d& dir, const std::vector<const Loop2*>& loops) {
  double best = std::numeric_limits<double>::infinity();
  for (const Loop2* loop : loops)
    for (size_t i = 0; i < loop->size(); ++i) {
      const Vector2d& a = (*loop)[i];
      const Vector2d e = (*loop)[(i + 1) % loop->size()] - a;
      const double denom = dir.x() * e.y() - dir.y() * e.x();
      if (denom == 0.0) continue;
      const Vector2d w = a - p;
      const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
      const double s = (w.x() * dir.y() - w.y() * dir.x()) / denom;
      if (t > 0.0 && s >= 0.0 && s <= 1.0) best = std::min(best, t);
    }
  return best;
}

// Sorted heights at which the vertical line x meets the loops' edges.
std::vector<double> vertical_crossings(double x, const std::vector<const Loop2*>& loops) {
  std::vector<double> ys;
  for (const Loop2* loop : loops)
    for (size_t i = 0; i < loop->size(); ++i) {
      const Vector2d& a = (*loop)[i];
      const Vector2d& b = (*loop)[(i + 1) % loop->size()];
      if ((a.x() <= x) == (b.x() <= x)) continue;  // half-open rule: each crossing counted once
      ys.push_back(a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y()));
    }
  std::sort(ys.begin(), ys.end());
  return ys;
}

Vector2d area_centroid(const Loop2& loop) {
  double a = 0.0;
  Vector2d c = Vector2d::Zero();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vector2d& p = loop[i];
    const Vector2d& q = loop[(i + 1) % loop.size()];
    const double w = p.x() * q.y() - p.y() * q.x();
    a += w;
    c += w * (p + q);
  }
  return a != 0.0 ? Vector2d(c / (3.0 * a)) : loop.front();
}

void set_grain_line(CuttingPiece& piece, double fraction) {
  const Vector2d c = area_centroid(piece.sew.front());
  // Nudge off vertices so the crossing count is clean.
  const double x = c.x() + 1e-9;
  const std::vector<double> ys = vertical_crossings(x, piece.cut.loops());
  // The inside interval that holds the centroid, or else the longest one.
  double lo = c.y(), hi = c.y();
  for (size_t i = 0; i + 1 < ys.size(); i += 2) {
    const bool contains = ys[i] <= c.y() && c.y() <= ys[i + 1];
    if (contains) {
      lo = ys[i];
      hi = ys[i + 1];
      break;
    }
    if (ys[i + 1] - ys[i] > hi - lo) {
      lo = ys[i];
      hi = ys[i + 1];
    }
  }
  const double mid = 0.5 * (lo + hi), half = 0.5 * fraction * (hi - lo);
  piece.grain_from = Vector2d(c.x(), mid - half);
  piece.grain_to = Vector2d(c.x(), mid + half);
}

// A notch at position k of the sew loop: along the outward normal of the loop's edge
// `direction_edge` (-1: the mean of the normals of the two edges at the vertex), starting where
// that line meets the cut line.
void add_notch(CuttingPiece& piece, const Loop2& sew, int k, int direction_edge, const PieceParams& params) {
  const int n = static_cast<int>(sew.size());
  const Vector2d& p = sew[k];
  Vector2d normal;
  if (direction_edge >= 0) {
    normal = outward_normal(sew[direction_edge], sew[(direction_edge + 1) % n]);
  } else {
    normal = (outward_normal(sew[(k + n - 1) % n], p) + outward_normal(p, sew[(k + 1) % n])).normalized();
  }
  if (!normal.allFinite()) return;
  const double d = params.allowance.allowance;
  double reach = 0.0;
  if (d > 0.0) reach = std::min(ray_hit(p, normal, piece.cut.loops()), params.allowance.mitre_limit * d);
  const Vector2d at = p + reach * normal;
  const double depth = d > 0.0 ? std::min(params.notch_depth, reach) : params.notch_depth;
  piece.notches.push_back({at, -normal, depth});
}

// Position in `side` of the vertex at half its pattern length.
int middle_index(const MatrixX2d& P, const std::vector<int>& side) {
  const double half = 0.5 * pattern_length(P, side);
  double walked = 0.0;
  for (size_t i = 1; i < side.size(); ++i) {
    walked += (P.row(side[i]) - P.row(side[i - 1])).norm();
    if (walked >= half) return static_cast<int>(i);
  }
  return static_cast<int>(side.size()) / 2;
}

// Where a pattern vertex sits in its piece's sew loops.
struct LoopPlace {
  int loop = -1, position = -1;
};

void add_seam_notches(CuttingLayout& layout, const Garment& g, const PieceParams& params,
                      const std::vector<std::vector<LoopPlace>>& place_of_vertex) {
  for (const Seam& seam : layout.seams) {
    const int m = static_cast<int>(seam.a.vertices.size());
    std::vector<int> marks{0};
    if (!seam.closed) marks.push_back(m - 1);
    if (m > 2 && pattern_length(g.P, seam.a.vertices, seam.closed) >= params.balance_notch_length)
      marks.push_back(middle_index(g.P, seam.a.vertices));
    for (const SeamSide* side : {&seam.a, &seam.b}) {
      CuttingPiece& piece = layout.pieces[side->panel];
      const std::vector<LoopPlace>& places = place_of_vertex[side->panel];
      for (int i : marks) {
        const int v = side->vertices[i];
        const LoopPlace at = places[v];
        if (at.loop < 0) continue;
        const Loop2& sew = piece.sew[at.loop];
        const int n = static_cast<int>(sew.size());
        // Seam ends are notched square to the seam's own last edge; other marks use the vertex normal.
        int edge = -1;
        const bool end = !seam.closed && (i == 0 || i == m - 1);
        if (end && m > 1) {
          const LoopPlace other = places[side->vertices[i == 0 ? 1 : m - 2]];
          if (other.position == (at.position + 1) % n) edge = at.position;
          else if (at.position == (other.position + 1) % n) edge = other.position;
        }
        add_notch(piece, sew, at.position, edge, params);
      }
    }
  }
}

} // namespace

CuttingLayout cutting_pieces(const Garment& g, const PieceParams& params) {
  CuttingLayout layout;
  layout.loops = panel_boundaries(g);
  layout.seams = seams(g, layout.loops);
  const int panels = static_cast<int>(g.panels.size());
  layout.pieces.resize(panels);
  std::vector<std::vector<LoopPlace>> place_of_vertex(panels);
  for (int p = 0; p < panels; ++p) {
    CuttingPiece& piece = layout.pieces[p];
    piece.panel = p;
    piece.name = g.panels[p].name;
    std::vector<int> own;
    for (int l = 0; l < static_cast<int>(layout.loops.size()); ++l)
      if (layout.loops[l].panel == p) own.push_back(l);
    if (own.empty()) throw ArgumentError("panel '" + piece.name + "' has no boundary");
    // Outer loop first (largest area); loops turned so that the material is on their left.
    std::vector<Loop2> loops;
    for (int l : own) loops.push_back(loop_points(g.P, layout.loops[l].vertices));
    size_t outer = 0;
    for (size_t i = 1; i < loops.size(); ++i)
      if (std::abs(signed_area(loops[i])) > std::abs(signed_area(loops[outer]))) outer = i;
    const bool flip = signed_area(loops[outer]) < 0.0;
    std::vector<size_t> order{outer};
    for (size_t i = 0; i < loops.size(); ++i)
      if (i != outer) order.push_back(i);
    place_of_vertex[p].assign(g.P.rows(), LoopPlace{});
    for (size_t k = 0; k < order.size(); ++k) {
      std::vector<int> vertices = layout.loops[own[order[k]]].vertices;
      if (flip) std::reverse(vertices.begin(), vertices.end());
      for (size_t i = 0; i < vertices.size(); ++i)
        if (place_of_vertex[p][vertices[i]].loop < 0)
          place_of_vertex[p][vertices[i]] = {static_cast<int>(k), static_cast<int>(i)};
      piece.sew.push_back(loop_points(g.P, vertices));
    }
    const std::vector<Loop2> holes(piece.sew.begin() + 1, piece.sew.end());
    try {
      piece.cut = seam_allowance(piece.sew.front(), holes, params.allowance);
    } catch (const ArgumentError& e) {
      throw ArgumentError("panel '" + piece.name + "': " + e.what());
    }
    set_grain_line(piece, params.grain_fraction);
  }
  add_seam_notches(layout, g, params, place_of_vertex);

  std::vector<Loop2> outlines;
  for (const CuttingPiece& piece : layout.pieces) outlines.push_back(piece.sew.front());
  for (const PanelPair& pair : congruent_panels(outlines, params.pair_tolerance)) {
    layout.pieces[pair.a].partner = pair.b;
    layout.pieces[pair.b].partner = pair.a;
    layout.pieces[pair.a].partner_match = layout.pieces[pair.b].partner_match = pair.match;
  }
  return layout;
}

std::vector<CuttingPiece> merge_congruent_pieces(const std::vector<CuttingPiece>& pieces) {
  std::vector<CuttingPiece> merged;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const CuttingPiece& piece = pieces[i];
    if (piece.partner && *piece.partner < static_cast<int>(i)) continue;  // folded into its partner
    CuttingPiece kept = piece;
    if (piece.partner) {
      kept.quantity = 2;
      kept.merged = pieces[*piece.partner].name;
    }
    kept.partner.reset();
    merged.push_back(std::move(kept));
  }
  return merged;
}

} // namespace foldsketch
