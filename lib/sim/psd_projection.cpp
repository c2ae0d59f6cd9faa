#include "sim/psd_projection.h"

#include <Eigen/Eigenvalues>

namespace foldsketch {

template <int N>
void project_to_psd(Eigen::Matrix<double, N, N>& H) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(H);
  if (eigen.eigenvalues().minCoeff() >= 0.0) return;
  const Eigen::Matrix<double, N, 1> clamped = eigen.eigenvalues().cwiseMax(0.0);
  H = eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

template void project_to_psd<9>(Eigen::Matrix<double, 9, 9>&);
template void project_to_psd<12>(Eigen::Matrix<double, 12, 12>&);

} // namespace foldsketch
