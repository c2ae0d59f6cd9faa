// The garment: 2D panels (the sewing patterns, rest shape), their 3D drape, and the sewing
// between them. Seams are implicit: a drape vertex used by two panels is a sewn point (the
// convention of Marvelous Designer / CLO OBJ exports and ARCSim meshes). Sewing that a shared
// vertex cannot express (many-to-one pleat stitches, gathered seams after remeshing) is an
// explicit stitch.
#pragma once

#include <string>
#include <vector>

#include "core/types.h"

namespace foldsketch {

struct Panel {
  std::string name;
  bool operator==(const Panel&) const = default;
};

// A point of the drape: drape vertex v0, or the point (1-t) V(v0) + t V(v1) on an edge.
struct StitchPoint {
  int v0 = -1;
  int v1 = -1;     // -1: the point is vertex v0
  double t = 0.0;  // in [0, 1], used when v1 >= 0
  bool operator==(const StitchPoint&) const = default;
};

// Two drape points sewn together (zero rest distance).
struct Stitch {
  StitchPoint a, b;
  bool operator==(const Stitch&) const = default;
};

struct Garment {
  MatrixX3d V;           // #V by 3 drape positions [m]
  MatrixX2d P;           // #P by 2 pattern positions [m]; each pattern vertex in one panel
  MatrixX3i F;           // #F by 3 triangles into V
  MatrixX3i FP;          // #F by 3 the same triangles into P
  VectorXi face_panel;   // #F panel index of each triangle; triangles are sorted by panel
  std::vector<Panel> panels;
  std::vector<Stitch> stitches;
};

// Exact equality of every array and list (positions compared bit for bit).
bool operator==(const Garment& a, const Garment& b);

// #P by 1 drape vertex of each pattern vertex (-1 where no triangle uses it).
VectorXi pattern_to_drape(const Garment& g);

// Triangles of panel p, in order.
std::vector<int> panel_faces(const Garment& g, int p);

// Rows FP(f) of the triangles of panel p.
MatrixX3i panel_pattern_faces(const Garment& g, int p);

// Empty when g is structurally sound, else what is wrong: array sizes, indices out of range,
// a pattern vertex used with two drape vertices or by two panels, unsorted or unknown panel
// ids, stitches naming missing vertices. Geometry (degenerate or flipped triangles) is
// checked by garment_issues(), not here.
std::string garment_structure_error(const Garment& g);

} // namespace foldsketch
