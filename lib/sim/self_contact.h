// Cloth-cloth contact, for the places that need it (pleats, layers pressed together): a
// penalty between a vertex and a triangle it does not belong to, on their unsigned distance d,
//   E = k A / 2 (t - d)^2  for d < t,
// the same law as body contact (k [N/m^3], A the vertex's rest area share, t the thickness).
// A vertex is pushed by the nearest triangle of each layer near it, not by every triangle in
// reach: over a shared edge or corner of a sheet it would otherwise be pushed two to six times.
// (Where the nearest triangle changes, to a neighbour, both are at the same distance with the
// same gradient there, so the energy stays continuously differentiable.)
//
// Two edges get the same law on their distance, with a third of their vertices' mean area (as
// in Incremental Potential Contact, Li et al. 2020: every edge pair, whichever features are
// closest, faded out as the edges turn parallel), so that edges crossing between vertices are
// pushed apart too. An earlier version weighted edge pairs by where the closest points lie on
// the edges; those weights are ill-conditioned for nearly parallel edges and left a sheet
// resting on a sheet at a residual floor of 1e-6. And each step is bounded so
// that no vertex passes through a triangle and no edge through an edge between two states
// (conservative advancement: along a straight step the distance between two elements shrinks
// at most by their largest relative corner move).
//
// What it does not do: untangle layers that already intersect at the start (the penalty is on
// the unsigned distance, so it holds them on whichever side they are).
#pragma once

#include <array>
#include <vector>

#include "core/types.h"
#include "mesh/triangle_geometry.h"
#include "sim/bending.h"

namespace foldsketch {

// Which cloth takes part, and how. Built once per model (cloth_model).
struct SelfContactModel {
  std::vector<int> vertices;                 // drape vertices that take part
  std::vector<std::array<int, 3>> triangles; // triangles whose corners all take part
  std::vector<std::array<int, 2>> edges;     // edges of those triangles, each once
  // Per drape vertex: itself and the vertices stitched to it, sorted. A vertex is never pushed
  // away from an element with a corner in this set (its own triangles, or those across a seam).
  std::vector<std::vector<int>> near;
  double thickness = 0;                      // [m]
  double stiffness = 0;                      // [N/m^3]
};

// Closest points of segments p0 p1 and q0 q1: p0 + s (p1 - p0) and q0 + t (q1 - q0).
struct SegmentClosestPoints {
  double s = 0, t = 0, distance = 0;
};
SegmentClosestPoints segment_closest_parameters(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1);
double segment_segment_distance(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1);

// Penalty of edge (p0, p1) against edge (q0, q1), with k = stiffness times the pair's area
// share [N/m]: E = m k/2 (t - d)^2 for segment distance d < t, with m the parallel-edge
// mollifier. Energy, gradient and exact Hessian (when want_hessian) over (p0, p1, q0, q1).
Element12 edge_edge_penalty(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1, double thickness,
                            double k, bool want_hessian);

// The same penalty's energy alone, without derivatives (line searches).
double edge_edge_energy(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1, double thickness, double k);

// Penalty of vertex p against triangle (a, b, c), with k = stiffness times p's area [N/m]:
// energy, gradient and exact Hessian over (p, a, b, c). Zero beyond the thickness.
Element12 point_triangle_penalty(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c, double thickness,
                                 double k, bool want_hessian);

// Vertex-triangle pairs (vertex, index into model.triangles) closer than `radius` in drape x,
// skipping pairs that share a vertex or a stitch (model.near). Sorted, each once.
std::vector<std::array<int, 2>> self_contact_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius);

// Edge-edge pairs (indices into model.edges, first < second) closer than `radius`, skipping
// pairs that share a vertex or a stitch. Sorted.
std::vector<std::array<int, 2>> self_contact_edge_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius);

// The vertex-triangle pairs in contact (closer than the thickness) that act: for each vertex, its nearest
// triangle, then the next nearest sharing no corner with one taken, and so on (one per layer).
std::vector<std::array<int, 2>> self_contact_active_pairs(const SelfContactModel& model, const MatrixX3d& x);

// Largest alpha in [0, 1] such that moving every vertex by alpha * dx (#V x 3) keeps each
// vertex-triangle and edge-edge pair at least `keep` times its present distance apart, by
// alpha * (largest relative move of their corners) <= (1 - keep) * distance. Pairs already
// touching (distance 0) cannot be protected and are skipped.
double self_contact_step_bound(const SelfContactModel& model, const MatrixX3d& x, const MatrixX3d& dx, double keep);

} // namespace foldsketch
