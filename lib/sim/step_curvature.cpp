#include "sim/step_curvature.h"

#include "core/error.h"

namespace foldsketch {
namespace {

// The Laplacian is only positive semi-definite for a garment with no pinned vertex (constants
// are its null space, and the targets' fit is blind to them: their right-hand side sums to
// zero). A diagonal this small relative to its entries (of order 1) picks the solution without
// a constant part and changes no other.
constexpr double kRegularisation = 1e-9;
// A drape triangle whose F^T F has a determinant below this fraction of its squared trace is
// collapsed (its F has no inverse on its plane): it sets no target.
constexpr double kCollapsed = 1e-12;

} // namespace

StepCurvature::StepCurvature(const ClothModel& model, const ClothEnergy& energy) : model_(model), energy_(energy) {
  gradients_.reserve(model.triangles.size());
  for (const MembraneRest& rest : model.rest) gradients_.push_back(shape_gradients(rest));
  SparseMatrix laplacian = energy.scalar_laplacian();
  for (int a = 0; a < energy.free_count(); ++a) laplacian.coeffRef(a, a) += kRegularisation;
  laplacian_.compute(laplacian);
  if (laplacian_.info() != Eigen::Success) throw ArgumentError("StepCurvature: the pattern's Laplacian did not factorise");
}

VectorXd StepCurvature::operator()(const MatrixX3d& x, const VectorXd& dx) const {
  using Matrix32 = Eigen::Matrix<double, 3, 2>;
  const std::vector<int>& free_index = energy_.free_index();
  const int n = energy_.free_count();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  for (size_t t = 0; t < model_.triangles.size(); ++t) {
    const auto& v = model_.triangles[t];
    const Eigen::Matrix<double, 2, 3>& b = gradients_[t];
    Matrix32 F = Matrix32::Zero(), dF = Matrix32::Zero();
    for (int i = 0; i < 3; ++i) {
      F += x.row(v[i]).transpose() * b.col(i).transpose();
      if (const int a = free_index[v[i]]; a >= 0) dF += dx.segment<3>(3 * a) * b.col(i).transpose();
    }
    const Eigen::Matrix2d FtF = F.transpose() * F;
    const double trace = FtF.trace();
    if (!(FtF.determinant() > kCollapsed * trace * trace)) continue;
    const Matrix32 G = -0.5 * F * FtF.inverse() * (dF.transpose() * dF);
    for (int i = 0; i < 3; ++i)
      if (const int a = free_index[v[i]]; a >= 0) rhs.row(a) += model_.rest[t].area * (G * b.col(i)).transpose();
  }
  const Eigen::MatrixXd c = laplacian_.solve(rhs);
  VectorXd out = VectorXd::Zero(3 * n);
  if (!c.allFinite()) return out;
  for (int a = 0; a < n; ++a) out.segment<3>(3 * a) = c.row(a).transpose();
  return out;
}

} // namespace foldsketch
