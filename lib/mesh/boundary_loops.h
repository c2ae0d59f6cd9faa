// Boundary loops of a triangle mesh.
#pragma once

#include <vector>

#include "core/types.h"

namespace foldsketch {

// Closed boundary loops of the triangles F, each a list of vertex indices in the order of the
// boundary half-edges (so a counter-clockwise triangle leaves its outer boundary
// counter-clockwise). A boundary edge is one with exactly one incident face. Loops start at
// their smallest vertex index and are sorted by it, so the result is deterministic. Where a
// vertex has several outgoing boundary half-edges (a "bow tie"), the loops through it are split
// there; every boundary half-edge is in exactly one loop.
std::vector<std::vector<int>> boundary_loops(const MatrixX3i& F, int num_vertices);

} // namespace foldsketch
