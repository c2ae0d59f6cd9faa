// Stored drapes for the benchmark's warm rows: a drape's vertex positions, kept in the
// repository so that a re-drape starts from the same equilibrium whatever solver is under test
// (the cold drape from the sewn placement is chaotic, so a start computed by the solver moves
// with every solver change; bench/README.md).
//
// File: a binary little-endian PLY with one element, vertex (float x, y, z [m]), and the comment
// "foldsketch-rest-mesh FINGERPRINT": the fingerprint of the mesh the positions belong to
// (mesh_fingerprint), so a start is never applied to another mesh. float keeps the files half
// the size; its rounding (under 0.1 um at 1 m) only fixes which start it is.
#pragma once

#include <cstdint>
#include <string>

#include "garment/garment.h"

namespace foldsketch {

// FNV-1a (64 bit) over the triangles, the pattern and the sewn placement's bytes: changes when
// the sample's mesh, patterns or placement change.
std::uint64_t mesh_fingerprint(const Garment& g);

// Where start k (1, 2, ...) of the skirt mesh with `triangles` triangles is kept in `folder`:
// folder/skirt-TRIANGLES-K.ply.
std::string stored_start_path(const std::string& folder, long triangles, int k);

// Writes x atomically (formats/atomic_file.h). `comment` goes into the header (one line).
void write_stored_start(const std::string& path, const MatrixX3d& x, std::uint64_t fingerprint, const std::string& comment);

// Reads a stored start for a mesh with `vertices` vertices and `fingerprint`; throws InputError
// "path:line: what is wrong" when the file is malformed or belongs to another mesh.
MatrixX3d read_stored_start(const std::string& path, Eigen::Index vertices, std::uint64_t fingerprint);

} // namespace foldsketch
