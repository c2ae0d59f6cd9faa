// Laying pieces out on a sheet without overlap: rows of bounding boxes (shelf packing), tallest
// first. Not a marker (nesting for fabric use); a drawing and print layout.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "core/types.h"

namespace foldsketch {

struct SheetLayout {
  std::vector<Vector2d> offsets;   // add to item i's coordinates to place it [m]
  Eigen::AlignedBox2d extent;      // the placed items' union, starting at (0, 0) [m]
};

// Places the boxes in rows from the top (y decreasing, as read on a page) with `gap` [m] between
// neighbours. Rows are about as wide as the square root of twice the total box area, and never
// narrower than the widest box.
SheetLayout shelf_layout(const std::vector<Eigen::AlignedBox2d>& boxes, double gap);

} // namespace foldsketch
