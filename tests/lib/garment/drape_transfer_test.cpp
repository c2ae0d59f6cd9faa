#include "garment/drape_transfer.h"

#include <algorithm>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// An affine map of the pattern plane into space: the drape of a flat panel, bent nowhere.
MatrixX3d affine_drape(const Garment& g) {
  Eigen::Matrix<double, 2, 3> A;
  A << 0.3, -0.7, 0.2, 0.5, 0.1, -0.9;
  const Eigen::RowVector3d t(0.01, 0.02, 0.03);
  MatrixX3d V(g.V.rows(), 3);
  for (int f = 0; f < g.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) V.row(g.F(f, k)) = g.P.row(g.FP(f, k)) * A + t;
  return V;
}

TEST(DrapeTransfer, ReproducesAnAffineDrapeOnAnotherMeshing) {
  const Garment coarse = test::square_panel(3, 1.0), fine = test::square_panel(11, 1.0);
  const MatrixX3d V = transfer_drape(coarse, affine_drape(coarse), fine);
  EXPECT_LT((V - affine_drape(fine)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(DrapeTransfer, OntoItsOwnMeshingIsTheIdentity) {
  const Garment g = test::two_sewn_squares();
  MatrixX3d drape = g.V;
  drape.col(2) = (g.V.col(0).array() * 3.0).sin().matrix();  // bent, so that only the vertices themselves match
  EXPECT_LT((transfer_drape(g, drape, g) - drape).cwiseAbs().maxCoeff(), 1e-15);
}

// g with every triangle split into four at its edge midpoints (pattern and drape alike, so
// that a seam's midpoint is one drape vertex of both panels).
Garment subdivided(const Garment& g) {
  Garment s = g;
  std::map<std::pair<int, int>, int> drape_midpoint, pattern_midpoint;
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector2d> P;
  const auto midpoint = [](auto& table, auto& added, const auto& positions, int a, int b) {
    const auto key = std::minmax(a, b);
    if (const auto it = table.find(key); it != table.end()) return it->second;
    added.push_back(0.5 * (positions.row(a) + positions.row(b)));
    return table[key] = static_cast<int>(positions.rows() + added.size() - 1);
  };
  s.F.resize(4 * g.F.rows(), 3);
  s.FP.resize(4 * g.F.rows(), 3);
  s.face_panel.resize(4 * g.F.rows());
  for (int f = 0; f < g.F.rows(); ++f) {
    const auto split = [&](const MatrixX3i& T, MatrixX3i& out, auto& table, auto& added, const auto& positions) {
      const int a = T(f, 0), b = T(f, 1), c = T(f, 2);
      const int ab = midpoint(table, added, positions, a, b), bc = midpoint(table, added, positions, b, c),
                ca = midpoint(table, added, positions, c, a);
      out.row(4 * f) << a, ab, ca;
      out.row(4 * f + 1) << ab, b, bc;
      out.row(4 * f + 2) << ca, bc, c;
      out.row(4 * f + 3) << ab, bc, ca;
    };
    split(g.F, s.F, drape_midpoint, V, g.V);
    split(g.FP, s.FP, pattern_midpoint, P, g.P);
    s.face_panel.segment<4>(4 * f).setConstant(g.face_panel(f));
  }
  s.V.conservativeResize(g.V.rows() + static_cast<long>(V.size()), 3);
  for (size_t i = 0; i < V.size(); ++i) s.V.row(g.V.rows() + static_cast<long>(i)) = V[i];
  s.P.conservativeResize(g.P.rows() + static_cast<long>(P.size()), 2);
  for (size_t i = 0; i < P.size(); ++i) s.P.row(g.P.rows() + static_cast<long>(i)) = P[i];
  return s;
}

TEST(DrapeTransfer, CarriesACurvedDrapeAcrossTheSkirtsSeams) {
  // Onto the subdivided skirt, a drape carries over exactly: its vertices where they were, the
  // new ones at the midpoints of the drape's edges, the side seams' ones too (each is found
  // from both panels' patterns, which must agree).
  const Garment skirt = test::skirt_on_body(800).skirt.garment;
  MatrixX3d drape = skirt.V;
  drape.col(2) += 0.05 * (20.0 * skirt.V.col(0).array()).sin().matrix();  // folds, so no interpolation is exact by accident
  Garment drape_skirt = skirt;
  drape_skirt.V = drape;
  const MatrixX3d V = transfer_drape(skirt, drape, subdivided(skirt));
  EXPECT_LT((V - subdivided(drape_skirt).V).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DrapeTransfer, CarriesTheSkirtAcrossSizes) {
  // The samples at two sizes are the same skirt up to how their grids meet the curved outline
  // (the pattern heights differ by 2 mm); the 6400-triangle placement lands within that of the
  // 5000-triangle one.
  const test::SkirtOnBody coarse = test::skirt_on_body(6400), fine = test::skirt_on_body(5000);
  const VectorXd distance =
      (transfer_drape(coarse.skirt.garment, coarse.skirt.garment.V, fine.skirt.garment) - fine.skirt.garment.V).rowwise().norm();
  EXPECT_LT(distance.maxCoeff(), 1e-3);
  EXPECT_LT(distance.mean(), 0.5e-3);
}

TEST(DrapeTransfer, RefusesGarmentsWithOtherPanelsOrAWrongDrape) {
  const Garment square = test::square_panel(3, 1.0), sewn = test::two_sewn_squares();
  EXPECT_THROW(transfer_drape(square, square.V, sewn), ArgumentError);
  EXPECT_THROW(transfer_drape(square, MatrixX3d::Zero(3, 3), square), ArgumentError);
}

} // namespace
} // namespace foldsketch
