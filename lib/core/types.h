// Glossary of the matrix names used across foldsketch (after libigl). Units are SI: metres.
//   V   #V by 3  drape (3D) vertex positions [m]
//   P   #P by 2  pattern (2D) vertex positions [m]
//   F   #F by 3  triangles as indices into V (counter-clockwise seen from the pattern's front)
//   FP  #F by 3  the same triangles as indices into P (corner k of F(f) is corner k of FP(f))
#pragma once

#include <Eigen/Core>

namespace foldsketch {

using Eigen::MatrixX2d;
using Eigen::MatrixX2i;
using Eigen::MatrixX3d;
using Eigen::MatrixX3i;
using Eigen::MatrixXd;
using Eigen::MatrixXi;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;
using Eigen::VectorXi;

// Deformation gradient of one triangle from its 2D rest shape to its 3D drape.
using Matrix32d = Eigen::Matrix<double, 3, 2>;

} // namespace foldsketch
