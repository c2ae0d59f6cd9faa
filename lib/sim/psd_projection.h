// Making element Hessians positive semi-definite, so Newton's system stays SPD.
#pragma once

#include <Eigen/Core>

namespace foldsketch {

// Replace the negative eigenvalues of the symmetric matrix H by zero (the closest PSD matrix
// in the Frobenius norm). H is read as symmetric.
template <int N>
void project_to_psd(Eigen::Matrix<double, N, N>& H);

} // namespace foldsketch
