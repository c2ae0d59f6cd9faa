// Body (and other obstacle) meshes: anything assimp reads (OBJ, PLY, STL, glTF, ...), taken
// to be in metres. All meshes of the file are merged, node transforms applied, polygons
// triangulated and vertices at the same position welded. assimp keeps single-precision
// positions: coordinates are rounded to about 1e-7 relative (0.1 um on a body), far below any
// contact thickness. OBJ files of triangles and quadrilaterals are read by our own reader
// (body_obj.h), to the same mesh, in about a quarter of the time.
#pragma once

#include <string>

#include "mesh/primitive_meshes.h"

namespace foldsketch {

TriangleMesh read_body_mesh(const std::string& path);

// Plain OBJ (v and f lines, exact numbers), written atomically.
void write_mesh_obj(const TriangleMesh& mesh, const std::string& path);

} // namespace foldsketch
