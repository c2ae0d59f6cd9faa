// ClothEnergy's rest-shape Laplacian, the drape solver's step metric, and the compressive
// stress that weights it (its energy terms are tested in derivatives_test.cpp).
#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "samples/grid_garment.h"
#include "sim/cloth_energy.h"
#include "sim/membrane.h"
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

TEST(ClothEnergy, WeightedLaplacianMatrixAndProductAgree) {
  Garment g;
  const ClothModel model = crumpled_sheet(g);
  const ClothEnergy energy(model);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> positive(0.01, 3.0);
  std::normal_distribution<double> normal;
  VectorXd weights(static_cast<Eigen::Index>(model.triangles.size()));
  for (Eigen::Index t = 0; t < weights.size(); ++t) weights(t) = positive(rng);
  SparseMatrix A = energy.pattern();
  energy.add_laplacian(A, 1.5, &weights);
  VectorXd d(3 * energy.free_count());
  for (int i = 0; i < d.size(); ++i) d(i) = normal(rng);
  EXPECT_LT((A * d - 1.5 * energy.laplacian_times(d, &weights)).norm(), 1e-12 * (A * d).norm());
  // Weights of 2 everywhere: twice the plain Laplacian.
  const VectorXd twos = VectorXd::Constant(weights.size(), 2.0);
  EXPECT_LT((energy.laplacian_times(d, &twos) - 2.0 * energy.laplacian_times(d)).norm(), 1e-12 * d.norm());
}

// A flat sheet at its pattern size has no compressive stress, nor one stretched along both
// axes; squeezed along x, every triangle is compressed, its exact membrane Hessian is
// indefinite (the geometric stiffness of compression), and adding the compressive stress times
// the triangle's Laplacian term makes it positive semi-definite: the bound the stress-weighted
// step metric relies on (DrapeSettings::stress_metric_reference).
TEST(ClothEnergy, CompressiveStressBoundsTheGeometricStiffness) {
  GridPanel p = flat_panel("sheet", 6, 5, 0.3, 0.25, {0, 0, 0}, Vector3d::UnitX(), Vector3d::UnitY());
  const Garment g = grid_garment({p}, 1e-12);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  const ClothModel model = cloth_model(g, scene, nullptr, {});
  const ClothEnergy energy(model);
  EXPECT_LT(energy.compressive_stress(g.V).maxCoeff(), 1e-9);  // roundoff of the rest shape
  MatrixX3d stretched = g.V;
  stretched.col(0) *= 1.05;
  stretched.col(1) *= 1.02;
  EXPECT_EQ(energy.compressive_stress(stretched).maxCoeff(), 0.0);

  MatrixX3d squeezed = g.V;
  squeezed.col(0) *= 0.9;
  const VectorXd c = energy.compressive_stress(squeezed);
  // Uniaxial: E11 = (0.9^2 - 1) / 2, and the stress along x is the most compressive.
  const double e11 = 0.5 * (0.81 - 1.0);
  EXPECT_NEAR(c.minCoeff(), -model.stiffness.c11 * e11, 1e-9 * model.stiffness.c11);
  EXPECT_NEAR(c.maxCoeff(), -model.stiffness.c11 * e11, 1e-9 * model.stiffness.c11);
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    const auto& v = model.triangles[t];
    const MembraneRest& r = model.rest[t];
    const Element9 e = membrane_element(squeezed.row(v[0]), squeezed.row(v[1]), squeezed.row(v[2]), r, model.stiffness, true,
                                        HessianKind::Exact);
    const Eigen::Matrix<double, 2, 3> b = shape_gradients(r);
    const Eigen::Matrix3d laplacian = r.area * b.transpose() * b;
    Eigen::Matrix<double, 9, 9> bound = Eigen::Matrix<double, 9, 9>::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) bound.block<3, 3>(3 * i, 3 * j) = laplacian(i, j) * Eigen::Matrix3d::Identity();
    const double scale = e.hessian.norm();
    const Eigen::Matrix<double, 9, 9> exact = 0.5 * (e.hessian + e.hessian.transpose());
    const Eigen::Matrix<double, 9, 9> bounded = exact + c(static_cast<Eigen::Index>(t)) * bound;
    using Solver = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>;
    EXPECT_LT(Solver(exact).eigenvalues()(0), -1e-6 * scale) << t;
    EXPECT_GT(Solver(bounded).eigenvalues()(0), -1e-9 * scale) << t;
  }
}

} // namespace
} // namespace foldsketch
