// Signed distance to a body mesh: positive outside, negative inside, through a CGAL AABB tree
// of the body's triangles.
#pragma once

#include <memory>

#include "core/types.h"
#include "mesh/primitive_meshes.h"

namespace foldsketch {

struct BodyPoint {
  double distance = 0;  // signed [m]: positive on the side the closest triangle faces
  Vector3d normal;      // unit normal of the closest triangle (direction of increasing distance)
  Vector3d closest;     // closest point on the body [m]
};

class BodyDistance {
public:
  explicit BodyDistance(const TriangleMesh& body);
  ~BodyDistance();
  BodyDistance(BodyDistance&&) noexcept;
  BodyDistance& operator=(BodyDistance&&) noexcept;

  BodyPoint at(const Vector3d& p) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  MatrixX3d normals_;  // per body triangle
};

} // namespace foldsketch
