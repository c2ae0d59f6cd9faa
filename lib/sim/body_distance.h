// Signed distance to a body mesh: positive outside, negative inside, through a CGAL AABB tree
// of the body's triangles; and the faces, edges and corners near a point that make the body
// contact C1 at the mesh's concave creases (contact_features).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/types.h"
#include "mesh/primitive_meshes.h"

namespace foldsketch {

struct BodyPoint {
  double distance = 0;  // signed [m]: positive on the side the closest triangle faces
  Vector3d normal;      // unit normal of the closest triangle (direction of increasing distance)
  Vector3d closest;     // closest point on the body [m]
  int face = -1;        // the body triangle it lies on
};

// One term of the body contact near a point (see BodyDistance::contact_features): the closest
// point of a body face, edge or corner [m] and the term's weight (+1 faces and corners, -1
// edges). Where the closest point lies inside an edge (an edge's term, or a face's closest point
// on one of its edges), `edge` is that edge's unit direction (the distance's curvature is then
// (I - u u^T - e e^T) / d); otherwise zero.
struct BodyFeaturePoint {
  Vector3d closest;
  double weight = 1;
  Vector3d edge = Vector3d::Zero();
  bool on_face = false;  // the closest point lies inside a face: the distance has no curvature there
};

class BodyDistance {
public:
  explicit BodyDistance(const TriangleMesh& body);
  ~BodyDistance();
  BodyDistance(BodyDistance&&) noexcept;
  BodyDistance& operator=(BodyDistance&&) noexcept;

  BodyPoint at(const Vector3d& p) const;
  // Where the closest point to p on body triangle `face` lies: inside the face, on an edge
  // (BodyFeaturePoint::edge its direction) or at a corner. Only the exact contact Hessian needs
  // it (the curvature of the distance), so at() leaves it out.
  BodyFeaturePoint closest_on_face(const Vector3d& p, int face) const;
  // The terms of a C1 contact energy at p: every face, edge and corner of the body closer
  // than radius, faces and corners counted +1 and edges -1. Over a convex or flat part of the
  // body the terms cancel down to the closest feature, so sum_f w_f g(d_f) = g(distance) for
  // any g vanishing beyond radius; at a concave crease both sides remain, and the sum is C1
  // where the closest point jumps from one side to the other (the distance itself has a kink
  // there). Empty when no concave edge is within reach: then the closest point alone is exact.
  std::vector<BodyFeaturePoint> contact_features(const Vector3d& p, double radius) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  MatrixX3d normals_;  // per body triangle
  MatrixX3d vertices_;
  MatrixX3i faces_, face_edges_;             // per face: its corners, its edges (ab, bc, ca)
  std::vector<std::array<int, 2>> edges_;    // corners of each edge
  std::vector<char> face_near_concave_;      // per face: one of its edges is concave
};

} // namespace foldsketch
