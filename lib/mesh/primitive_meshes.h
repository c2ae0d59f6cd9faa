// Closed triangle meshes of simple solids, counter-clockwise seen from outside. Units follow
// the arguments (metres everywhere in foldsketch).
#pragma once

#include "core/types.h"

namespace foldsketch {

struct TriangleMesh {
  MatrixX3d V;  // #V by 3
  MatrixX3i F;  // #F by 3
};

// Axis-aligned box from corner lo to corner hi, two triangles per face.
TriangleMesh box_mesh(const Vector3d& lo, const Vector3d& hi);

// Capped cylinder along +y: axis through (x, z) = center, from y0 to y1, with `segments`
// vertices per ring.
TriangleMesh cylinder_mesh(const Eigen::Vector2d& center, double radius, double y0, double y1, int segments);

} // namespace foldsketch
