// Isotropic triangle meshes of planar polygons, keeping the outline's vertices exactly (no
// point is added on the outline, so two panels sampled alike on a seam stay sewable).
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"

namespace foldsketch {

struct PlanarMesh {
  MatrixX2d P;  // #P by 2; the outline's vertices first, in order
  MatrixX3i F;  // #F by 3, counter-clockwise
};

struct IsotropicMeshParams {
  // Interior points sit on a hexagonal lattice of this spacing [m], each moved by up to this
  // fraction of the spacing (deterministic, from `seed`): a perfectly regular lattice aligns
  // its edges, and hinge bending energies are measurably too soft on edge-aligned meshes
  // (tests/lib/sim/physics_test.cpp, cantilever).
  double jitter = 0.2;
  // Lattice points closer than this fraction of the spacing to the outline are dropped.
  double boundary_clearance = 0.6;
  std::uint32_t seed = 1;
};

// Constrained Delaunay triangulation (CGAL) of the closed polygon `outline` (#O by 2,
// counter-clockwise, simple) minus the `holes` (simple polygons inside it, disjoint, any
// orientation), with interior lattice points of the given spacing. P lists the outline's
// vertices first, then each hole's, in order.
PlanarMesh isotropic_mesh(const MatrixX2d& outline, double spacing, const IsotropicMeshParams& params = {},
                          const std::vector<MatrixX2d>& holes = {});

} // namespace foldsketch
