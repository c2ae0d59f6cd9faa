// Per-triangle maps from the 2D pattern (rest shape) to the 3D drape.
#pragma once

#include <vector>

#include "garment/garment.h"

namespace foldsketch {

// Deformation gradient of every triangle: the 3x2 matrix D with D (X_k - X_0) = x_k - x_0 for
// pattern corners X and drape corners x. Its singular values are the principal stretches.
// A triangle with zero pattern area gets a NaN matrix (garment_issues() reports it).
std::vector<Matrix32d> deformation_gradients(const Garment& g);

// #F by 2 principal stretches (largest first) of every triangle: 1 = unstretched.
MatrixX2d principal_stretches(const Garment& g);

} // namespace foldsketch
