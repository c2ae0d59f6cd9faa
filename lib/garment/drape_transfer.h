// Carries a drape from one meshing of a garment's patterns to another meshing of the same
// patterns: each target vertex takes the drape position of its pattern point in the source
// mesh (the source triangle of the same panel that contains it, or the nearest one, by
// barycentric interpolation of that triangle's drape corners). A vertex sewn across panels has
// one pattern point per panel; it takes their mean.
//
// For a drape that must follow its patterns onto a new mesh (pattern extension remeshes the
// extended panels, DESIGN 4.5), and between the levels of a coarse-to-fine drape
// (sim/coarse_to_fine.h).
#pragma once

#include "garment/garment.h"

namespace foldsketch {

// #to.V by 3: the drape from_V of `from` (#from.V by 3) at the pattern points of `to`. The
// garments must have the same panels, in the same order, with the same names; their pattern
// outlines should agree (a point outside the source panel takes its nearest source point).
// Throws ArgumentError otherwise.
MatrixX3d transfer_drape(const Garment& from, const MatrixX3d& from_V, const Garment& to);

} // namespace foldsketch
