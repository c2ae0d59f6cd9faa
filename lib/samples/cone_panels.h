// Panels cut from the frustum of an elliptic cone: a developable surface, so each panel
// unrolls exactly (every grid cell lies in a plane through the apex) and the sample drape is
// isometric to its patterns.
#pragma once

#include <vector>

#include "samples/grid_garment.h"

namespace foldsketch {

// An elliptic ring in a horizontal plane (y up): centre (cx, y, cz), semi-axes a along x and
// b along z.
struct EllipseRing {
  double cx = 0, cz = 0, y = 0, a = 0, b = 0;
  // phi from +x towards -z: increasing phi runs to the right seen from outside (y up), so a
  // panel whose columns follow phi faces outwards.
  Vector3d point(double phi) const;
};

// Angles splitting the ring into `count` arcs of equal length, starting at phi0 and going
// towards increasing phi.
std::vector<double> equal_arc_angles(const EllipseRing& ring, int count, double phi0);

// A panel between two rings that are scaled copies about a common apex (same centre and a/b
// ratio: a cone or, if equal, a cylinder), spanning angles phis[c0..c1]. Rows run from the
// lower ring (row 0) to the upper ring. The pattern is unrolled cell by cell and turned so the
// panel's middle ruling points along +y (the grain line).
GridPanel cone_panel(const std::string& name, const EllipseRing& lower, const EllipseRing& upper,
                     const std::vector<double>& phis, int c0, int c1, int rows);

} // namespace foldsketch
