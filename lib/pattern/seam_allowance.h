// Seam allowance: the cut line of a pattern piece, offset outwards from its sew line.
//
// The offset region is the exact union (CGAL Boolean set operations, exact kernel) of the piece,
// one rectangle per outline edge swept outwards by the allowance, and one join polygon per convex
// corner. A union of simple polygons is a valid polygon with holes whatever the outline looks
// like: concave corners, edges much shorter than the allowance, strips narrower than twice the
// allowance and holes come out without self-intersections, where offsetting edge by edge and
// reconnecting would cross itself.
#pragma once

#include <vector>

#include "core/types.h"

namespace foldsketch {

// A closed polygon: vertices in order, the closing edge implied.
using Loop2 = std::vector<Vector2d>;

struct AllowanceParams {
  double allowance = 0.010;  // [m]; 10 mm, the usual industrial seam allowance
  // Convex corners are mitred (the two offset lines extended until they meet) while the mitre
  // point lies within mitre_limit * allowance of the sew-line corner, i.e. for interior angles of
  // 2 asin(1/mitre_limit) = 60 degrees and more; sharper corners are squared off at that distance.
  // 2: the SVG/PostScript default, and what pattern makers do by hand (a needle-sharp allowance
  // corner cannot be cut or sewn).
  double mitre_limit = 2.0;
};

struct CutOutline {
  Loop2 outer;                // counter-clockwise
  std::vector<Loop2> holes;   // clockwise: internal cut-outs that survive the offset

  // Every loop of the cut line, outer first.
  std::vector<const Loop2*> loops() const;
};

// Cut outline of the region bounded by `outer` (counter-clockwise) minus `holes` (clockwise,
// inside outer, disjoint). allowance 0 returns the input unchanged. Cut-line vertices within
// 1 nm of the segment between their neighbours are dropped. Every cut vertex lies at least one
// allowance from the outline and at most allowance * sqrt(mitre_limit^2 + 1) (a squared corner).
// Throws ArgumentError on non-finite input, an outer loop of fewer than 3 vertices or a negative
// allowance.
CutOutline seam_allowance(const Loop2& outer, const std::vector<Loop2>& holes, const AllowanceParams& params = {});

// Outward unit normal of the edge a -> b of a loop with the material on its left.
Vector2d outward_normal(const Vector2d& a, const Vector2d& b);

// Signed area of a loop (positive when counter-clockwise) [m^2].
double signed_area(const Loop2& loop);

// True when no two non-adjacent edges of the loop touch and no adjacent edges overlap (exact
// predicates).
bool is_simple(const Loop2& loop);

// Distance from p to the nearest point of the closed loop's edges.
double distance_to_loop(const Vector2d& p, const Loop2& loop);

} // namespace foldsketch
