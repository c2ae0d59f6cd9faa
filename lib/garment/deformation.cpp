#include "garment/deformation.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <Eigen/SVD>

namespace foldsketch {

std::vector<Matrix32d> deformation_gradients(const Garment& g) {
  std::vector<Matrix32d> D(static_cast<size_t>(g.F.rows()));
  for (int f = 0; f < g.F.rows(); ++f) {
    Eigen::Matrix2d rest;
    rest.col(0) = (g.P.row(g.FP(f, 1)) - g.P.row(g.FP(f, 0))).transpose();
    rest.col(1) = (g.P.row(g.FP(f, 2)) - g.P.row(g.FP(f, 0))).transpose();
    Matrix32d drape;
    drape.col(0) = (g.V.row(g.F(f, 1)) - g.V.row(g.F(f, 0))).transpose();
    drape.col(1) = (g.V.row(g.F(f, 2)) - g.V.row(g.F(f, 0))).transpose();
    const double det = rest.determinant();
    if (det == 0.0) D[f].setConstant(std::numeric_limits<double>::quiet_NaN());
    else D[f] = drape * rest.inverse();
  }
  return D;
}

MatrixX2d principal_stretches(const Garment& g) {
  const std::vector<Matrix32d> D = deformation_gradients(g);
  MatrixX2d S(g.F.rows(), 2);
  for (int f = 0; f < g.F.rows(); ++f) {
    if (!D[f].allFinite()) { S.row(f).setConstant(std::numeric_limits<double>::quiet_NaN()); continue; }
    Eigen::JacobiSVD<Matrix32d> svd(D[f]);
    S.row(f) = svd.singularValues().transpose();
  }
  return S;
}

} // namespace foldsketch
