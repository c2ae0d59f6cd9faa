// Merge vertices that sit at the same place.
#pragma once

#include "core/types.h"

namespace foldsketch {

// #V by 1 index of the welded vertex of each row of V: rows closer than tolerance (Euclidean)
// share an index. Welded vertices are numbered in order of their first row, and each keeps
// the position of that first row (see welded_positions).
VectorXi weld_vertices(const MatrixX3d& V, double tolerance);

// Positions of the welded vertices: the first row of V mapped to each index.
MatrixX3d welded_positions(const MatrixX3d& V, const VectorXi& weld);

} // namespace foldsketch
