// Connected components of a triangle mesh.
#pragma once

#include "core/types.h"

namespace foldsketch {

// #F by 1 component id of each triangle, where two triangles are connected when they share a
// vertex of F. Ids are 0, 1, ... in order of each component's first triangle.
VectorXi face_components(const MatrixX3i& F, int num_vertices);

} // namespace foldsketch
