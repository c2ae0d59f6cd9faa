// The second-order part of a Newton step that follows rotations: a curved path
// x + a dx + a^2 c for the line search instead of the straight x + a dx.
//
// Why: in a static drape's long tail (folds rolling, regions of cloth turning as a whole) the
// Newton model's error at a full step is the membrane's alone and grows as a^2 along the step.
// A straight step along a rotation stretches each triangle by the Green strain of the step's
// own gradient, dF^T dF / 2, and the stiff membrane answers with forces several times the
// residual (10K skirt: 7.7 |g| at a full step; bench/drape_bench.txt), so the line search cuts
// the step or the next iteration spends itself undoing the stretch. Rotating a triangle by W
// (skew) to second order moves it by W F + W^2 F / 2, and the second term is what takes the
// stretch away. In general c removes the excess to first order in c: sym(F^T grad c) =
// -dF^T dF / 2, met per triangle by grad c = G = -F (F^T F)^-1 dF^T dF / 2 (= W^2 F / 2 for a
// rotation). The per-triangle targets do not fit together exactly, so c is their least-squares
// fit over the pattern, min sum_t A_t |grad c - G_t|^2: one solve with the pattern's Laplacian,
// a constant matrix factorised once per drape. (Weighting the fit by the membrane's stiffness
// at the stepped drape removes the excess nearly exactly, 7.7 |g| -> 0.02 |g|, but needs a
// factorisation of its own every iteration and was slower in wall time; measured in
// bench/drape_bench.txt.)
#pragma once

#include <vector>

#include <Eigen/SparseCholesky>

#include "sim/cloth_energy.h"

namespace foldsketch {

class StepCurvature {
public:
  // Factorises energy's pattern Laplacian (ClothEnergy::scalar_laplacian); both arguments must
  // outlive this object.
  StepCurvature(const ClothModel& model, const ClothEnergy& energy);
  // c for the Newton step dx (3 per free vertex, [m]) from drape x (#V by 3): what x + a dx +
  // a^2 c adds to the straight step. Pinned vertices do not move; triangles collapsed in the
  // drape contribute no target; a non-finite solve gives c = 0.
  VectorXd operator()(const MatrixX3d& x, const VectorXd& dx) const;

private:
  const ClothModel& model_;
  const ClothEnergy& energy_;
  std::vector<Eigen::Matrix<double, 2, 3>> gradients_;  // per triangle: shape-function gradients over the pattern
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> laplacian_;
};

} // namespace foldsketch
