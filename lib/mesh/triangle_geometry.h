// Per-triangle measures of a mesh in 2D (#V by 2) or 3D (#V by 3). Units follow V.
#pragma once

#include "core/types.h"

namespace foldsketch {

// #F by 1 twice the area of each triangle. For 2D vertices the area is signed: positive for
// counter-clockwise triangles. For 3D vertices it is the (non-negative) magnitude.
VectorXd double_areas(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F);

// #F by 3 edge lengths: column k is the length of the edge opposite corner k.
MatrixX3d edge_lengths(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F);

// #F by 3 interior angles [rad]: column k is the angle at corner k. A triangle with a
// zero-length edge gets NaN angles at the corners that edge touches.
MatrixX3d internal_angles(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F);

// Smallest interior angle of each triangle [rad]; 0 for a degenerate triangle.
VectorXd min_angles(const Eigen::Ref<const MatrixXd>& V, const MatrixX3i& F);

// The closest point on triangle (a, b, c) to p: barycentric weights (summing to 1) and which
// feature it lies on: 0 the face, 1-3 the edges ab, bc, ca, 4-6 the corners a, b, c.
struct TriangleClosestPoint {
  Vector3d weights;
  int feature = 0;
};
TriangleClosestPoint closest_point_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c);

double point_triangle_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c);

} // namespace foldsketch
