// A coarser meshing of a garment's patterns, sewn like the original: for draping coarse to
// fine (sim/coarse_to_fine.h), where a cold drape forms its folds on few triangles and the fine
// mesh only refines them.
#pragma once

#include "garment/garment.h"

namespace foldsketch {

// Each panel remeshed isotropically (mesh/isotropic_mesh.h) with edges of about `spacing` [m]
// inside and along its outline. The outline keeps a subset of the original boundary vertices:
// every corner and seam end (garment/boundary_runs.h), then vertices about `spacing` apart
// along each run, chosen once per seam (by its first side's length) so that both sides keep
// the same drape vertices and stay sewn. Panels keep their names and order; the drape is
// carried over by transfer_drape. Throws ArgumentError for a garment with explicit stitches
// (a coarser mesh cannot carry them yet), a spacing that is not positive, or one that leaves
// some boundary loop with fewer than three vertices. original_vertex, when given, gets for
// each drape vertex of the result the drape vertex of g it is (the kept outline vertices), or -1.
Garment coarse_garment(const Garment& g, double spacing, VectorXi* original_vertex = nullptr);

// The spacing that gives about `triangles` triangles for g's pattern area (a lattice of
// spacing s has triangles of area sqrt(3)/4 s^2).
double spacing_for_triangles(const Garment& g, int triangles);

} // namespace foldsketch
