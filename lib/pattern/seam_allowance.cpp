#include "pattern/seam_allowance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include "core/error.h"

namespace foldsketch {
namespace {
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

Point exact(const Vector2d& p) { return Point(p.x(), p.y()); }

double cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The polygon through `points`, counter-clockwise; nothing when it has no area.
std::optional<Polygon> ccw_polygon(const std::vector<Vector2d>& points) {
  Polygon polygon;
  for (const Vector2d& p : points) polygon.push_back(exact(p));
  const auto sign = CGAL::sign(polygon.area());
  if (sign == CGAL::ZERO) return std::nullopt;
  if (sign == CGAL::NEGATIVE) polygon.reverse_orientation();
  return polygon;
}

// The polygons whose union with the piece is its offset: a rectangle per edge and a join per
// convex corner. Rectangle and join share their corner points bit for bit, so the union has no
// slivers of gap between them.
void add_offset_pieces(const Loop2& loop, const AllowanceParams& params, std::vector<Polygon>& pieces) {
  const int n = static_cast<int>(loop.size());
  const double d = params.allowance;
  std::vector<Vector2d> normal(n), tangent(n);
  std::vector<bool> usable(n);
  for (int i = 0; i < n; ++i) {
    const Vector2d e = loop[(i + 1) % n] - loop[i];
    usable[i] = e.norm() > 0.0;
    tangent[i] = usable[i] ? Vector2d(e.normalized()) : Vector2d::Zero();
    normal[i] = usable[i] ? outward_normal(loop[i], loop[(i + 1) % n]) : Vector2d::Zero();
  }
  for (int i = 0; i < n; ++i) {
    if (!usable[i]) continue;
    const Vector2d& a = loop[i];
    const Vector2d& b = loop[(i + 1) % n];
    if (auto rect = ccw_polygon({a, b, b + d * normal[i], a + d * normal[i]})) pieces.push_back(*rect);
  }
  for (int i = 0; i < n; ++i) {
    // Corner at loop[i] between the edge into it (i-1) and the edge out of it (i); zero-length
    // edges are skipped over.
    int in = (i + n - 1) % n;
    while (!usable[in] && in != i) in = (in + n - 1) % n;
    if (!usable[in] || !usable[i]) continue;
    const Vector2d& v = loop[i];
    const Vector2d t1 = tangent[in], t2 = tangent[i], n1 = normal[in], n2 = normal[i];
    const double turn = std::atan2(cross(t1, t2), t1.dot(t2));  // > 0: convex corner
    if (!(turn > 0.0)) continue;
    const Vector2d p1 = v + d * n1, p2 = v + d * n2;
    // The join as triangles: a triangle with area is always simple, where a near-straight
    // quadrilateral v, p1, mitre, p2 can come out self-touching in floating point; a join left
    // out would leave a crack in the union down to the sew line.
    const auto add_triangle = [&](const Vector2d& a, const Vector2d& b, const Vector2d& c) {
      if (auto triangle = ccw_polygon({a, b, c})) pieces.push_back(*triangle);
    };
    add_triangle(v, p1, p2);
    const double mitre_length = 1.0 / std::cos(0.5 * turn);  // in allowances
    if (turn < 3.0 && mitre_length <= params.mitre_limit) {
      add_triangle(p1, v + d * (n1 + n2) / (1.0 + n1.dot(n2)), p2);
    } else {
      // Square the corner: cut the mitre perpendicular to the bisector at mitre_limit * d.
      const Vector2d sum = n1 + n2;
      const Vector2d b = sum.norm() > 1e-9 ? Vector2d(sum.normalized()) : t1;
      const double reach = params.mitre_limit * d;
      const Vector2d c1 = p1 + (reach - d * n1.dot(b)) / t1.dot(b) * t1;
      const Vector2d c2 = p2 - (reach - d * n2.dot(b)) / -t2.dot(b) * t2;
      add_triangle(p1, c1, c2);
      add_triangle(p1, c2, p2);
    }
  }
}

// Vertices closer than this to the segment between their neighbours are dropped from the cut
// line [m]: the union leaves such vertices where a join meets a rectangle along a line that is
// straight only up to the roundoff of the points computed on it (1 nm: far below any cutter).
constexpr double kStraightTolerance = 1e-9;

// Boundary vertices as doubles, without the ones that lie on the segment between their
// neighbours (within kStraightTolerance).
Loop2 simplified(const Polygon& polygon) {
  Loop2 loop;
  for (auto v = polygon.vertices_begin(); v != polygon.vertices_end(); ++v)
    loop.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
  bool changed = true;
  while (changed && loop.size() > 3) {
    changed = false;
    Loop2 kept;
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      const Vector2d& prev = kept.empty() ? loop[(i + n - 1) % n] : kept.back();
      const Vector2d& next = loop[(i + 1) % n];
      const Vector2d e = next - prev;
      const double along = (loop[i] - prev).dot(e);
      const bool between = along > 0.0 && along < e.squaredNorm();
      const bool straight = between && std::abs(cross(e, loop[i] - prev)) <= kStraightTolerance * e.norm();
      if (straight && kept.size() + (n - i) > 3) {
        changed = true;
        continue;
      }
      kept.push_back(loop[i]);
    }
    loop.swap(kept);
  }
  return loop;
}

void check_loop(const Loop2& loop, const char* what) {
  if (loop.size() < 3) throw ArgumentError(std::string("seam_allowance: the ") + what + " has fewer than 3 vertices");
  for (const Vector2d& p : loop)
    if (!p.allFinite()) throw ArgumentError(std::string("seam_allowance: the ") + what + " has a non-finite vertex");
}
} // namespace

std::vector<const Loop2*> CutOutline::loops() const {
  std::vector<const Loop2*> all{&outer};
  for (const Loop2& h : holes) all.push_back(&h);
  return all;
}

Vector2d outward_normal(const Vector2d& a, const Vector2d& b) {
  const Vector2d t = (b - a).normalized();
  return {t.y(), -t.x()};
}

double signed_area(const Loop2& loop) {
  double twice = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) twice += cross(loop[i], loop[(i + 1) % loop.size()]);
  return 0.5 * twice;
}

bool is_simple(const Loop2& loop) {
  Polygon polygon;
  for (const Vector2d& p : loop) polygon.push_back(exact(p));
  return polygon.is_simple();
}

double distance_to_loop(const Vector2d& p, const Loop2& loop) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vector2d& a = loop[i];
    const Vector2d& b = loop[(i + 1) % loop.size()];
    const Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

CutOutline seam_allowance(const Loop2& outer, const std::vector<Loop2>& holes, const AllowanceParams& params) {
  check_loop(outer, "outer outline");
  for (const Loop2& h : holes) check_loop(h, "hole outline");
  if (!(params.allowance >= 0.0) || !std::isfinite(params.allowance))
    throw ArgumentError("seam_allowance: the allowance must be a finite number >= 0");
  if (!(params.mitre_limit >= 1.0)) throw ArgumentError("seam_allowance: the mitre limit must be >= 1");
  if (params.allowance == 0.0) return {outer, holes};

  std::vector<Polygon> pieces;
  add_offset_pieces(outer, params, pieces);
  for (const Loop2& h : holes) add_offset_pieces(h, params, pieces);

  Polygon outer_polygon;
  for (const Vector2d& p : outer) outer_polygon.push_back(exact(p));
  if (!outer_polygon.is_simple() || outer_polygon.orientation() != CGAL::COUNTERCLOCKWISE)
    throw ArgumentError("seam_allowance: the outer outline must be counter-clockwise and simple");
  CGAL::Polygon_set_2<Kernel> region(outer_polygon);
  for (const Loop2& h : holes) {
    Polygon hole;
    for (const Vector2d& p : h) hole.push_back(exact(p));
    if (!hole.is_simple()) throw ArgumentError("seam_allowance: a hole outline crosses itself");
    if (hole.orientation() == CGAL::CLOCKWISE) hole.reverse_orientation();
    region.difference(hole);
  }
  region.join(pieces.begin(), pieces.end());

  std::vector<PolygonWithHoles> parts;
  region.polygons_with_holes(std::back_inserter(parts));
  if (parts.size() != 1) throw ArgumentError("seam_allowance: the cut outline is not one piece");
  CutOutline cut;
  cut.outer = simplified(parts[0].outer_boundary());
  for (auto h = parts[0].holes_begin(); h != parts[0].holes_end(); ++h) cut.holes.push_back(simplified(*h));
  return cut;
}

} // namespace foldsketch
