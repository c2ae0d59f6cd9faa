// Body meshes in Wavefront OBJ, read without assimp. Every tool that meets a body reads one,
// and assimp takes 0.2-0.27 s for the 1.9 MB GarmentCode body in a process's first read (most
// of it setting up its importers) where this reader takes about 60 ms.
//
// It gives what read_body_mesh gives through assimp for the same file: the faces' vertices in
// the order the faces first use them (unused v lines dropped), vertices at the same position
// welded, quadrilaterals split from a reflex corner as assimp's triangulation does, and
// positions rounded to single precision, so a drape does not depend on which reader read its
// body. Points and lines (p, l) are skipped, as are texture coordinates, normals, groups and
// materials.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "mesh/primitive_meshes.h"

namespace foldsketch {

// The mesh in `text` (the contents of the OBJ file at `path`, named in errors), or nothing when
// a face has more than four corners (a polygon for assimp's triangulation). Throws InputError
// "path:line: ..." for a malformed v or f line or an index out of range.
std::optional<TriangleMesh> parse_body_obj(std::string_view text, const std::string& path);

} // namespace foldsketch
