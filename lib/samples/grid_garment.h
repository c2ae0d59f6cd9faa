// Garments made of structured grid panels, for the sample scenes: each panel is a grid of
// nodes with a pattern position and a drape position; panels are sewn wherever their drape
// nodes coincide.
#pragma once

#include <string>
#include <vector>

#include "garment/garment.h"

namespace foldsketch {

struct GridPanel {
  std::string name;
  // Node (i, j), i = column (pattern x grows with i), j = row (pattern y grows with j), is
  // stored at index j * columns + i. columns, rows >= 2. Pattern cells must be
  // counter-clockwise and the drape must keep that orientation seen from outside.
  int columns = 0, rows = 0;
  MatrixX2d pattern;  // columns*rows by 2 [m]
  MatrixX3d drape;    // columns*rows by 3 [m]
};

// Triangulate every cell (diagonals alternating like a chequerboard, so the mesh has no
// preferred shear direction) and weld drape nodes of all panels closer than weld_tolerance.
Garment grid_garment(const std::vector<GridPanel>& panels, double weld_tolerance);

// Mesh every panel isotropically instead (lib/mesh/isotropic_mesh.h, lattice spacing
// `spacing` [m]) keeping the grid's boundary nodes, so panels sewn along a grid boundary stay
// sewable; interior points are placed in the drape by the grid's own piecewise-linear map.
// Hinge bending is measurably too soft on edge-aligned grids (tests/lib/sim/physics_test.cpp),
// so the engine wants these meshes.
Garment isotropic_garment(const std::vector<GridPanel>& panels, double spacing, double weld_tolerance);

// A flat rectangular panel of nu x nv cells, width x height [m] in the pattern (x across, y up);
// in the drape, pattern (u, v) sits at origin + u * across + v * up (unit vectors).
GridPanel flat_panel(const std::string& name, int nu, int nv, double width, double height, const Vector3d& origin,
                     const Vector3d& across, const Vector3d& up);

// Lay the panels out side by side in pattern space, left to right in the given order with
// `gap` between their bounding boxes, bottoms on y = 0. Panels keep their shape.
void lay_out_patterns(std::vector<GridPanel>& panels, double gap);

} // namespace foldsketch
