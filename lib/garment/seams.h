// Panel boundaries and the seams between them, found from welded drape vertices.
#pragma once

#include <vector>

#include "garment/garment.h"

namespace foldsketch {

// One closed boundary loop of one panel: pattern vertex indices, counter-clockwise for the
// outer boundary of a counter-clockwise panel.
struct BoundaryLoop {
  int panel = -1;
  std::vector<int> vertices;
};

// Boundary loops of every panel, panels in order.
std::vector<BoundaryLoop> panel_boundaries(const Garment& g);

// One side of a seam: consecutive vertices of one boundary loop.
struct SeamSide {
  int panel = -1;
  int loop = -1;               // index into panel_boundaries()
  int begin = 0;               // position in the loop of vertices.front()
  std::vector<int> vertices;   // pattern vertices along the loop (wrapping around)
};

// Two boundary runs sewn together: a.vertices[i] and b.vertices[i] are the same drape vertex.
// Side a follows its loop forwards; side b, of consistently oriented panels, backwards.
// A closed seam (a whole loop sewn to a whole loop) repeats no vertex: the edge from the last
// vertex back to the first is sewn too.
struct Seam {
  SeamSide a, b;
  bool closed = false;
};

// Seams of g: maximal runs of boundary edges whose drape edge is a boundary edge of exactly
// two panel loops (or twice of one, for a panel sewn to itself). Deterministic order: by the
// loop and position of side a. Drape edges on three or more panel boundaries are not sewn here
// (garment_issues() reports them).
std::vector<Seam> seams(const Garment& g, const std::vector<BoundaryLoop>& loops);

// Pattern length of a run of pattern vertices [m]; closed adds the closing edge.
double pattern_length(const MatrixX2d& P, const std::vector<int>& vertices, bool closed = false);

// Drape length of a run of pattern vertices, measured on their drape vertices [m].
double drape_length(const Garment& g, const std::vector<int>& vertices, bool closed = false);

} // namespace foldsketch
