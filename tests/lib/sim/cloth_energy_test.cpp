// ClothEnergy's rest-shape Laplacian, the drape solver's step metric (its energy terms are
// tested in derivatives_test.cpp).
#include <random>

#include <gtest/gtest.h>

#include "samples/grid_garment.h"
#include "sim/cloth_energy.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// A 0.4 x 0.3 m sheet, its drape crumpled at random so that the pattern, not the drape,
// defines the Laplacian.
ClothModel crumpled_sheet(Garment& g) {
  GridPanel p = flat_panel("sheet", 8, 6, 0.4, 0.3, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (int v = 0; v < p.drape.rows(); ++v)
    for (int c = 0; c < 3; ++c) p.drape(v, c) += jitter(rng);
  g = grid_garment({p}, 1e-12);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  return cloth_model(g, scene, nullptr, {});
}

TEST(ClothEnergy, LaplacianMatrixAndProductAgree) {
  Garment g;
  const ClothModel model = crumpled_sheet(g);
  const ClothEnergy energy(model);
  SparseMatrix A = energy.pattern();
  energy.add_laplacian(A, 2.5);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  VectorXd d(3 * energy.free_count());
  for (int i = 0; i < d.size(); ++i) d(i) = normal(rng);
  const VectorXd Ld = energy.laplacian_times(d);
  EXPECT_LT((A * d - 2.5 * Ld).norm(), 1e-12 * (A * d).norm());
  EXPECT_GT(d.dot(Ld), 0.0);
  EXPECT_LT((A - SparseMatrix(A.transpose())).norm(), 1e-12 * A.norm());
}

// Over the pattern, d^T L d is the Dirichlet energy: zero for a translation, the pattern's
// area for a unit gradient along one pattern axis, whatever the drape.
TEST(ClothEnergy, LaplacianIsTheDirichletEnergyOfThePattern) {
  Garment g;
  const ClothModel model = crumpled_sheet(g);
  const ClothEnergy energy(model);
  const int n = energy.free_count();
  ASSERT_EQ(n, model.vertex_count) << "no pins";
  VectorXd shift(3 * n), ramp = VectorXd::Zero(3 * n);
  for (int a = 0; a < n; ++a) shift.segment<3>(3 * a) = Vector3d(0.3, -1.0, 2.0);
  const VectorXi drape_of = pattern_to_drape(g);  // one panel: one pattern vertex per drape vertex
  for (int q = 0; q < g.P.rows(); ++q) ramp(3 * energy.free_index()[drape_of(q)] + 1) = g.P(q, 0);  // u = pattern x, along y
  EXPECT_LT(energy.laplacian_times(shift).norm(), 1e-10);
  EXPECT_NEAR(ramp.dot(energy.laplacian_times(ramp)), 0.4 * 0.3, 1e-12);
}

} // namespace
} // namespace foldsketch
