// Pins: drape vertices held at fixed positions (a flag's pole edge, a skirt's waist).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "core/types.h"
#include "garment/garment.h"

namespace foldsketch {

struct Pin {
  int vertex = -1;   // drape vertex
  Vector3d position; // where it is held [m]
};

// Drape vertices inside the axis-aligned box (boundary included), in index order.
std::vector<int> vertices_in_box(const MatrixX3d& V, const Eigen::AlignedBox3d& box);

// Pins holding the given drape vertices where they are in V; duplicates removed, sorted.
std::vector<Pin> pins_at(const MatrixX3d& V, std::vector<int> vertices);

// A triangle edge with both drape ends pinned, and how long the pins hold it against its
// pattern length (drape / pattern; 1: at rest).
struct PinnedEdge {
  int v0 = -1, v1 = -1;  // drape vertices; -1 when no edge has both ends pinned
  double stretch = 1.0;
};

// Pins that hold an edge this much longer than its pattern hold the cloth between them far
// from any equilibrium a fabric has: the membrane presets are measured at strains of a few
// percent, and 50 % is beyond what woven cloth takes. A Berkeley Garment Library placement
// pinned at its top band holds edges at 6.5-9 times their length (the coarse blouse-short,
// dress3 and tank-female), and the solve then ends at 800 % strain without converging. Our choice.
constexpr double kLargestPinnedStretch = 1.5;

// Of the edges of g's triangles whose two drape ends are both in `pinned`, the one the pins
// hold longest against its pattern length (the first of equals in triangle order; within a
// triangle, in the order of the corners the edges face).
PinnedEdge most_stretched_pinned_edge(const Garment& g, const std::vector<int>& pinned);

} // namespace foldsketch
