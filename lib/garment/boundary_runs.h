// Corners of panel boundaries and the runs between them: the pieces of outline a pattern
// maker names ("side seam", "hem", "waist").
#pragma once

#include <vector>

#include "garment/seams.h"

namespace foldsketch {

struct CornerParams {
  // Turning angle of the outline [rad] above which a boundary vertex is a corner. 25 degrees:
  // our choice; pattern corners turn by 45 degrees or more, a curve sampled at 10K-triangle
  // resolution turns by a few degrees per vertex.
  double min_turning = 25.0 * 3.14159265358979323846 / 180.0;
};

// Positions (into loops[l].vertices) of the corners of each loop: vertices where the outline
// turns by more than params.min_turning, and the ends of every open seam side.
std::vector<std::vector<int>> boundary_corners(const Garment& g, const std::vector<BoundaryLoop>& loops,
                                               const std::vector<Seam>& seams, const CornerParams& params = {});

// A run of a loop from one corner to the next, both included.
struct BoundaryRun {
  int loop = -1;
  std::vector<int> vertices;  // pattern vertices; a loop without corners is one closed run
  bool closed = false;
};

std::vector<BoundaryRun> boundary_runs(const std::vector<BoundaryLoop>& loops,
                                       const std::vector<std::vector<int>>& corners);

} // namespace foldsketch
