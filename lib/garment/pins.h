// Pins: drape vertices held at fixed positions (a flag's pole edge, a skirt's waist).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "core/types.h"

namespace foldsketch {

struct Pin {
  int vertex = -1;   // drape vertex
  Vector3d position; // where it is held [m]
};

// Drape vertices inside the axis-aligned box (boundary included), in index order.
std::vector<int> vertices_in_box(const MatrixX3d& V, const Eigen::AlignedBox3d& box);

// Pins holding the given drape vertices where they are in V; duplicates removed, sorted.
std::vector<Pin> pins_at(const MatrixX3d& V, std::vector<int> vertices);

} // namespace foldsketch
