// Every energy term's gradient and Hessian against central finite differences, at random
// configurations, nearly degenerate triangles included (relative error < 1e-5).
#include <cmath>
#include <numbers>
#include <random>
#include <tuple>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "sim/bending.h"
#include "sim/cloth_energy.h"
#include "sim/membrane.h"
#include "sim/self_contact.h"
#include "samples/grid_garment.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

constexpr double kTolerance = 1e-5;

// Relative error of `analytic` against `numeric`, scaled by the larger of their norms.
double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  const double scale = std::max({analytic.norm(), numeric.norm(), 1e-300});
  return (analytic - numeric).norm() / scale;
}

// Central differences of f (value, gradient) at q with step h (relative to the geometry).
template <int N, typename F>
void check_derivatives(const Eigen::Matrix<double, N, 1>& q, double h, F f, const char* what) {
  const auto [e0, g0, H0] = f(q);
  Eigen::Matrix<double, N, 1> g_fd;
  Eigen::Matrix<double, N, N> H_fd;
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> qp = q, qm = q;
    qp(i) += h;
    qm(i) -= h;
    const auto [ep, gp, Hp] = f(qp);
    const auto [em, gm, Hm] = f(qm);
    g_fd(i) = (ep - em) / (2 * h);
    H_fd.col(i) = (gp - gm) / (2 * h);
  }
  EXPECT_LT(relative_error(g0, g_fd), kTolerance) << what << " gradient\n" << g0.transpose() << "\n" << g_fd.transpose();
  EXPECT_LT(relative_error(H0, H_fd), kTolerance) << what << " Hessian";
  EXPECT_LT(relative_error(H0, H0.transpose()), 1e-12) << what << " Hessian symmetry";
  (void)e0;
}

template <int N>
double smallest_eigenvalue(const Eigen::Matrix<double, N, N>& H) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>>(H).eigenvalues().minCoeff();
}

Vector3d corner(const Eigen::VectorXd& q, int k) { return q.segment<3>(3 * k); }

TEST(Derivatives, MembraneAtRandomConfigurations) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Material cotton = *material_preset("cotton-thin");
  Material anisotropic = *material_preset("denim");
  anisotropic.poisson = 0.3;
  for (const Material& m : {cotton, anisotropic}) {
    const MembraneStiffness k = membrane_stiffness(m);
    // A regular triangle, a 0.5-degree sliver and a needle of 0.01 degrees.
    for (const double apex : {0.9, 0.0044, 8.7e-5}) {
      const MembraneRest rest = membrane_rest({0, 0}, {0.01, 0}, {0.005, 0.01 * apex});
      for (int trial = 0; trial < 10; ++trial) {
        Eigen::Matrix<double, 9, 1> q;
        q << 0, 0, 0, 0.01, 0, 0, 0.005, 0.01 * apex, 0;
        for (int i = 0; i < 9; ++i) q(i) += 0.002 * noise(rng);  // stretch, shear, compress and bend
        const double h = 1e-7;
        check_derivatives<9>(q, h, [&](const Eigen::Matrix<double, 9, 1>& x) {
          const Element9 e = membrane_element(corner(x, 0), corner(x, 1), corner(x, 2), rest, k, true, HessianKind::Exact);
          return std::make_tuple(e.energy, e.gradient, e.hessian);
        }, "membrane");
      }
    }
  }
}

TEST(Derivatives, DihedralAngleAndHingeAtRandomConfigurations) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (const double flap : {1.0, 0.02, 0.0087}) {  // regular, 1-degree and 0.5-degree flaps
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::Matrix<double, 12, 1> q;
      q << 0, 0, 0, 1, 0, 0, 0.4, flap, 0, 0.6, -flap, 0;
      for (int i = 0; i < 12; ++i) q(i) += 0.1 * flap * noise(rng);
      q.segment<3>(9) += Vector3d(0, 0, flap * std::sin(trial * 0.3));  // fold up to ~ +-75 degrees
      const double h = 1e-6 * flap;
      check_derivatives<12>(q, h, [&](const Eigen::Matrix<double, 12, 1>& x) {
        const DihedralAngle a = dihedral_angle(corner(x, 0), corner(x, 1), corner(x, 2), corner(x, 3), true);
        return std::make_tuple(a.theta, a.gradient, a.hessian);
      }, "dihedral angle");
      check_derivatives<12>(q, h, [&](const Eigen::Matrix<double, 12, 1>& x) {
        const Element12 e = hinge_element(corner(x, 0), corner(x, 1), corner(x, 2), corner(x, 3), 2.5e-6, 0.1, true,
                                          HessianKind::Exact);
        return std::make_tuple(e.energy, e.gradient, e.hessian);
      }, "hinge");
    }
  }
}

TEST(Derivatives, ProjectedHessiansArePositiveSemiDefinite) {
  const MembraneStiffness k = membrane_stiffness(*material_preset("cotton-thin"));
  const MembraneRest rest = membrane_rest({0, 0}, {1, 0}, {0, 1});
  // Compressed to 60 %: stress negative, exact Hessian indefinite.
  const Element9 exact = membrane_element({0, 0, 0}, {0.6, 0, 0}, {0, 0.6, 0}, rest, k, true, HessianKind::Exact);
  const Element9 projected = membrane_element({0, 0, 0}, {0.6, 0, 0}, {0, 0.6, 0}, rest, k, true, HessianKind::Projected);
  EXPECT_LT(smallest_eigenvalue(exact.hessian), -1e-3);
  EXPECT_GT(smallest_eigenvalue(projected.hessian), -1e-9);
  const Element12 hinge = hinge_element({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -0.5, 0.8}, 1.0, 0.0, true, HessianKind::Projected);
  EXPECT_GT(smallest_eigenvalue(hinge.hessian), -1e-9);
}

// The energy-only functions the line search calls give the element functions' energies to the
// last bit (a different rounding could flip a line-search decision), slivers and collapsed
// triangles included.
TEST(Derivatives, EnergyOnlyFunctionsMatchTheElementsExactly) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  const MembraneStiffness k = membrane_stiffness(*material_preset("cotton-thin"));
  for (const double apex : {0.9, 0.0044, 0.0}) {
    const MembraneRest rest = membrane_rest({0, 0}, {0.01, 0}, {0.005, 0.01 * std::max(apex, 1e-6)});
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::Matrix<double, 12, 1> q;
      q << 0, 0, 0, 0.01, 0, 0, 0.005, 0.01 * apex, 0, 0.005, -0.01, 0;
      for (int i = 0; i < 12; ++i) q(i) += 0.002 * noise(rng);
      if (trial == 0) q.segment<3>(6) = 0.5 * (q.segment<3>(0) + q.segment<3>(3));  // collapsed triangle
      EXPECT_EQ(membrane_energy(corner(q, 0), corner(q, 1), corner(q, 2), rest, k),
                membrane_element(corner(q, 0), corner(q, 1), corner(q, 2), rest, k, false, HessianKind::Exact).energy);
      EXPECT_EQ(hinge_energy(corner(q, 0), corner(q, 1), corner(q, 2), corner(q, 3), 2.5e-6, 0.1),
                hinge_element(corner(q, 0), corner(q, 1), corner(q, 2), corner(q, 3), 2.5e-6, 0.1, true, HessianKind::Exact).energy);
    }
  }
}

TEST(Bending, FlatHingeHasZeroAngleAndSignedFolds) {
  EXPECT_NEAR(dihedral_angle({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, false).theta, 0.0, 1e-15);
  // Fold the second flap up by 60 degrees (about the edge): |theta| = 60 degrees.
  const double a = M_PI / 3;
  const double theta = dihedral_angle({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -std::cos(a), std::sin(a)}, false).theta;
  EXPECT_NEAR(std::abs(theta), a, 1e-12);
  EXPECT_TRUE(dihedral_angle({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0.5, -1, 0}, false).degenerate);
}

} // namespace
} // namespace foldsketch

namespace foldsketch {
namespace {

// The assembled energy (membrane, bending, gravity, a stitch, body contact; one vertex pinned)
// against central differences over every free coordinate: checks the stitch, gravity and
// contact terms and the sparse assembly itself. The garment lies over a box's top face, inside
// the contact layer, where the contact Hessian k A n n^T is exact (flat face).
TEST(Derivatives, AssembledEnergyWithEveryTerm) {
  Garment g = test::two_sewn_squares();
  g.P *= 0.1;
  g.V *= 0.1;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int v = 0; v < g.V.rows(); ++v) g.V.row(v) = Vector3d(g.V(v, 0) + 0.05, 0.301, g.V(v, 1) + 0.05) + 0.002 * Vector3d(noise(rng), noise(rng), noise(rng));
  g.stitches.push_back({{0, -1, 0.0}, {2, 5, 0.3}});
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.body = BodySettings{"box", 0.003};
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.5, 0.3, 0.5});
  const ClothModel model = cloth_model(g, scene, &box, {4});
  const ClothEnergy energy(model);
  ASSERT_EQ(energy.free_count(), 5);

  VectorXd g0;
  SparseMatrix H;
  const EnergyTerms terms = energy.evaluate(g.V, &g0, &H, HessianKind::Exact);
  ASSERT_GT(terms.contact, 0.0);
  ASSERT_GT(terms.stitches, 0.0);
  // The energy alone (the line search's call) is the same to the last bit.
  EXPECT_EQ(energy.evaluate(g.V, nullptr, nullptr, HessianKind::Exact).total(), terms.total());
  const Eigen::MatrixXd dense = Eigen::MatrixXd(H);
  const double h = 1e-7;
  VectorXd g_fd(g0.size());
  Eigen::MatrixXd H_fd(g0.size(), g0.size());
  for (int a = 0; a < energy.free_count(); ++a)
    for (int c = 0; c < 3; ++c) {
      MatrixX3d plus = g.V, minus = g.V;
      plus(energy.free_vertices()[a], c) += h;
      minus(energy.free_vertices()[a], c) -= h;
      VectorXd gp, gm;
      const double ep = energy.evaluate(plus, &gp, nullptr, HessianKind::Exact).total();
      const double em = energy.evaluate(minus, &gm, nullptr, HessianKind::Exact).total();
      g_fd(3 * a + c) = (ep - em) / (2 * h);
      H_fd.col(3 * a + c) = (gp - gm) / (2 * h);
    }
  EXPECT_LT(relative_error(g0, g_fd), kTolerance);
  EXPECT_LT(relative_error(dense, H_fd), kTolerance);
}

// Contact is evaluated only where it can act: vertices certified out of contact by an earlier
// query skip the body. The result must be the same, bit for bit, as evaluating afresh.
TEST(Derivatives, ContactCertificatesChangeNothing) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.5, 0.3, 0.5});
  Garment g = test::square_panel(12, 0.4);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> height(0.295, 0.36);  // some vertices inside the 3 mm layer
  for (int v = 0; v < g.V.rows(); ++v) g.V.row(v) = Vector3d(g.V(v, 0) + 0.05, height(rng), g.V(v, 1) + 0.05);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.body = BodySettings{"box", 0.003};
  const ClothModel model = cloth_model(g, scene, &box, {});
  const ClothEnergy reused(model);
  std::normal_distribution<double> step(0.0, 0.004);
  MatrixX3d x = g.V;
  int in_contact = 0;
  for (int k = 0; k < 20; ++k) {
    VectorXd g1, g2;
    SparseMatrix H1 = reused.pattern(), H2;
    const EnergyTerms a = reused.evaluate(x, &g1, &H1, HessianKind::Exact);
    const ClothEnergy fresh(model);
    H2 = fresh.pattern();
    const EnergyTerms b = fresh.evaluate(x, &g2, &H2, HessianKind::Exact);
    EXPECT_EQ(a.contact, b.contact) << "evaluation " << k;
    EXPECT_EQ(a.total(), b.total());
    EXPECT_EQ((g1 - g2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(Eigen::MatrixXd(H1 - H2).cwiseAbs().maxCoeff(), 0.0);
    in_contact += a.contact > 0.0 ? 1 : 0;
    for (int v = 0; v < x.rows(); ++v) x.row(v) += Vector3d(step(rng), step(rng), step(rng)).transpose();
  }
  EXPECT_GT(in_contact, 10);  // the comparison covered contact, not only free flight
}

// A vertex in the contact layer over the crease of a V trough, on its bisector, where the
// closest body triangle changes from one slope to the other: the contact energy is C1 there
// (one penalty on the distance to the closest triangle has a kink, and Newton stalled on it),
// so its derivatives match central differences and its force does not jump across.
TEST(Derivatives, BodyContactOnAConcaveCrease) {
  const TriangleMesh trough = test::v_trough(10.0);
  for (int f = 0; f < trough.F.rows(); ++f) {  // faces up
    const Vector3d a = trough.V.row(trough.F(f, 0)), b = trough.V.row(trough.F(f, 1)), c = trough.V.row(trough.F(f, 2));
    ASSERT_GT((b - a).cross(c - a).y(), 0.0);
  }
  Garment g = test::square_panel(2, 0.02);
  for (int v = 0; v < g.V.rows(); ++v) g.V.row(v) = Vector3d(g.P(v, 0) - 0.01, 0.0015, g.P(v, 1) - 0.01);
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.body = BodySettings{"trough", 0.003};
  const ClothModel model = cloth_model(g, scene, &trough, {0, 1, 2, 3, 5, 6, 7, 8});
  const ClothEnergy energy(model);
  ASSERT_EQ(energy.free_count(), 1);
  ASSERT_DOUBLE_EQ(g.V(4, 2), 0.0);  // the free vertex is on the bisector

  const auto contact = [&](const Eigen::Vector3d& q) {
    MatrixX3d x = g.V;
    x.row(4) = q.transpose();
    VectorXd grad;
    SparseMatrix H = energy.pattern();
    const EnergyTerms e = energy.evaluate(x, &grad, &H, HessianKind::Exact);
    return std::make_tuple(e.total(), Eigen::Vector3d(grad), Eigen::Matrix3d(Eigen::MatrixXd(H)));
  };
  const Eigen::Vector3d q = g.V.row(4).transpose();
  ASSERT_GT(std::get<0>(contact(q)), 0.0);
  check_derivatives<3>(q, 1e-7, contact, "contact on the crease");
  const Eigen::Vector3d left = std::get<1>(contact(q - Eigen::Vector3d(0, 0, 1e-9)));
  const Eigen::Vector3d right = std::get<1>(contact(q + Eigen::Vector3d(0, 0, 1e-9)));
  // A kink would make the force jump by about |force| 2 sin(10 deg); 2 nm of smooth change is
  // about 1e-5 of it.
  EXPECT_LT((left - right).norm(), 1e-4 * left.norm()) << left.transpose() << " | " << right.transpose();

  // Off the crease (2 mm to the side, over one slope only) the faces, edge and corners summed
  // near the crease cancel down to the one penalty on the distance to that slope's plane.
  const double slope = 10.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d aside(0.0, 0.0015 + 0.002 * std::tan(slope), -0.002);
  MatrixX3d x = g.V;
  x.row(4) = aside.transpose();
  const double to_plane = 0.0015 * std::cos(slope);  // height above the slope, along its normal
  const double depth = model.contact_thickness - to_plane;
  EXPECT_NEAR(energy.evaluate(x, nullptr, nullptr, HessianKind::Exact).contact,
              0.5 * model.contact_stiffness * model.contact_area(4) * depth * depth, 1e-12);
}

// A vertex in the contact layer beside a box's convex edge and beside its corner, where the
// closest body point lies on the edge or the corner and the distance curves: the exact contact
// Hessian keeps that curvature (negative sideways) and matches central differences; the
// Gauss-Newton one, which drops it, does not (the solver uses it away from equilibrium).
TEST(Derivatives, BodyContactBesideAConvexEdgeAndCorner) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.5, 0.3, 0.5});
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.body = BodySettings{"box", 0.003};
  for (const double z : {0.25, 0.5011}) {  // beside the edge x = 0.5, y = 0.3; beside the corner
    const char* what = z < 0.5 ? "contact beside an edge" : "contact beside a corner";
    Garment g = test::square_panel(2, 0.02);
    for (int v = 0; v < g.V.rows(); ++v) g.V.row(v) = Vector3d(0.5012 + g.P(v, 0) - 0.01, 0.3009, z + g.P(v, 1) - 0.01);
    const ClothModel model = cloth_model(g, scene, &box, {0, 1, 2, 3, 5, 6, 7, 8});
    const ClothEnergy energy(model);
    ASSERT_EQ(energy.free_count(), 1);
    const auto contact = [&](const Eigen::Vector3d& q, HessianKind kind) {
      MatrixX3d x = g.V;
      x.row(4) = q.transpose();
      VectorXd grad;
      SparseMatrix H = energy.pattern();
      const EnergyTerms e = energy.evaluate(x, &grad, &H, kind);
      EXPECT_GT(e.contact, 0.0) << what;
      return std::make_tuple(e.total(), Eigen::Vector3d(grad), Eigen::Matrix3d(Eigen::MatrixXd(H)));
    };
    const Eigen::Vector3d q = g.V.row(4).transpose();
    check_derivatives<3>(q, 1e-7, [&](const Eigen::Vector3d& y) { return contact(y, HessianKind::Exact); }, what);
    // The dropped curvature, k A (t - d) / d about 0.3 of k A here, is no rounding error.
    const Eigen::Matrix3d exact = std::get<2>(contact(q, HessianKind::Exact));
    const Eigen::Matrix3d dropped = std::get<2>(contact(q, HessianKind::GaussNewton));
    EXPECT_GT(relative_error(dropped, exact), 0.01) << what;
    EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(exact - dropped).eigenvalues().maxCoeff(), 1e-9) << what;
  }
}

// Self-contact penalty of a vertex against a triangle, with the vertex in each of the seven
// regions (face, three edges, three corners) of an ordinary and of a 0.5-degree sliver
// triangle, at 10-90 % of the contact thickness and away from region borders (where only the
// gradient is continuous).
TEST(Derivatives, SelfContactPenaltyInEveryRegion) {
  const double thickness = 1e-3, k = 100.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.1, 0.9);
  const double sliver = 0.5 * std::numbers::pi / 180;
  const std::array<std::array<Vector3d, 3>, 2> triangles{{
      {Vector3d(0, 0, 0), Vector3d(0.01, 0.001, 0.002), Vector3d(0.003, 0.009, -0.001)},
      {Vector3d(0, 0, 0), Vector3d(0.01, 0, 0), Vector3d(0.005, 0.005 * std::tan(sliver), 0)}}};
  for (const auto& [a, b, c] : triangles) {
    const Vector3d corners[3] = {a, b, c};
    for (int feature = 0; feature < 7; ++feature) {
      // The feature's nearest point to aim near: a face point, an edge point or the corner.
      int found = 0;
      for (int attempt = 0; attempt < 20000 && found < 3; ++attempt) {
        Vector3d target;
        if (feature == 0) {
          Vector3d w(fraction(rng), fraction(rng), fraction(rng));
          w /= w.sum();
          target = w(0) * a + w(1) * b + w(2) * c;
        } else if (feature <= 3) {
          const double s = fraction(rng);
          target = (1 - s) * corners[feature - 1] + s * corners[feature % 3];
        } else {
          target = corners[feature - 4];
        }
        const Vector3d p = target + fraction(rng) * thickness * Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
        Eigen::Matrix<double, 12, 1> q;
        q << p, a, b, c;
        const auto region = [](const Eigen::Matrix<double, 12, 1>& y) {
          return closest_point_on_triangle(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9)).feature;
        };
        const double d = point_triangle_distance(p, a, b, c);
        if (region(q) != feature || d < 0.1 * thickness || d > 0.9 * thickness) continue;
        bool inside = true;  // every finite-difference probe stays in the same region
        for (int i = 0; i < 12 && inside; ++i)
          for (const double step : {-1e-6, 1e-6}) {
            Eigen::Matrix<double, 12, 1> y = q;
            y(i) += step;
            inside = inside && region(y) == feature;
          }
        if (!inside) continue;
        ++found;
        check_derivatives<12>(q, 1e-9, [&](const Eigen::Matrix<double, 12, 1>& y) {
          const Element12 e = point_triangle_penalty(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9), thickness, k, true);
          return std::tuple{e.energy, e.gradient, e.hessian};
        }, ("self-contact region " + std::to_string(feature)).c_str());
      }
      EXPECT_EQ(found, 3) << "no configurations found in region " << feature;
    }
  }
}

// Edge-edge penalty for each pair of closest features (interior-interior, an end against an
// interior either way, end-end), at 10-90 % of the thickness, crossing at random angles and
// nearly parallel (inside the mollifier's range), away from feature borders.
TEST(Derivatives, EdgeEdgePenaltyForEveryFeaturePair) {
  const double thickness = 1e-3, k = 100.0;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.1, 0.9);
  const auto kind = [](const Eigen::Matrix<double, 12, 1>& y) {
    const SegmentClosestPoints c = segment_closest_parameters(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9));
    const auto place = [](double s) { return s <= 0.0 ? 0 : s >= 1.0 ? 2 : 1; };
    const Vector3d u = y.segment<3>(3) - y.segment<3>(0), v = y.segment<3>(9) - y.segment<3>(6);
    const bool mollified = u.cross(v).squaredNorm() < 1e-3 * u.squaredNorm() * v.squaredNorm();
    return 3 * place(c.s) + place(c.t) + (mollified ? 9 : 0);  // 4: both inside; +9: mollified
  };
  std::vector<int> found(18, 0);
  for (int attempt = 0; attempt < 200000; ++attempt) {
    // Edge p along x, 1 cm; edge q through a point near p's line at a random angle.
    const bool parallel = attempt % 3 == 0;
    const double angle = parallel ? 0.012 + 0.016 * fraction(rng) : 3.0 * fraction(rng);
    const Vector3d p0(0, 0, 0), p1(0.01, 0, 0);
    const Vector3d direction(std::cos(angle), std::sin(angle), 0.3 * unit(rng));
    const Vector3d centre(0.014 * unit(rng) + 0.005, 0.0005 * unit(rng), thickness * unit(rng));
    const Vector3d q0 = centre - 0.006 * (1 + 0.5 * unit(rng)) * direction.normalized(), q1 = centre + 0.006 * (1 + 0.5 * unit(rng)) * direction.normalized();
    Eigen::Matrix<double, 12, 1> q;
    q << p0, p1, q0, q1;
    const double d = segment_segment_distance(p0, p1, q0, q1);
    if (d < 0.1 * thickness || d > 0.9 * thickness) continue;
    const int type = kind(q);
    if (type >= 18 || found[static_cast<size_t>(type)] >= 2) continue;
    bool stable = true;
    for (int i = 0; i < 12 && stable; ++i)
      for (const double step : {-1e-6, 1e-6}) {
        Eigen::Matrix<double, 12, 1> y = q;
        y(i) += step;
        stable = stable && kind(y) == type;
      }
    if (!stable) continue;
    ++found[static_cast<size_t>(type)];
    // The cheaper evaluations (no Hessian; the energy alone) give the same energy and gradient.
    const Element12 full = edge_edge_penalty(p0, p1, q0, q1, thickness, k, true);
    const Element12 first = edge_edge_penalty(p0, p1, q0, q1, thickness, k, false);
    EXPECT_NEAR(first.energy, full.energy, 1e-12 * std::abs(full.energy));
    EXPECT_LE((first.gradient - full.gradient).norm(), 1e-12 * full.gradient.norm());
    EXPECT_TRUE(first.hessian.isZero());
    EXPECT_NEAR(edge_edge_energy(p0, p1, q0, q1, thickness, k), full.energy, 1e-9 * std::abs(full.energy)) << "case " << type;
    check_derivatives<12>(q, 1e-9, [&](const Eigen::Matrix<double, 12, 1>& y) {
      const Element12 e = edge_edge_penalty(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9), thickness, k, true);
      return std::tuple{e.energy, e.gradient, e.hessian};
    }, ("edge-edge case " + std::to_string(type)).c_str());
  }
  // Every feature pair crossing at an angle (the end-end cases too), and the interior case
  // nearly parallel.
  for (int type : {0, 1, 2, 3, 4, 5, 6, 7, 8}) EXPECT_EQ(found[static_cast<size_t>(type)], 2) << "case " << type;
  EXPECT_EQ(found[9 + 4], 2) << "nearly parallel, interior-interior";
}

// The assembled energy with self-contact: two stacked sheets, the upper one crumpled into the
// lower one's contact layer, against finite differences of the whole (after prepare()).
TEST(Derivatives, AssembledEnergyWithSelfContact) {
  Garment g = grid_garment({flat_panel("lower", 3, 3, 0.03, 0.03, {0, 0, 0.03}, Vector3d::UnitX(), -Vector3d::UnitZ()),
                            flat_panel("upper", 2, 2, 0.02, 0.02, {0.004, 0.0006, 0.025}, Vector3d::UnitX(), -Vector3d::UnitZ())},
                           1e-9);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> jitter(-0.0003, 0.0003);
  for (int v = 16; v < g.V.rows(); ++v) g.V.row(v) += Vector3d(jitter(rng), jitter(rng), jitter(rng)).transpose();
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  scene.physics.self_contact = true;
  const ClothModel model = cloth_model(g, scene, nullptr, {0, 3, 12, 15});
  ClothEnergy energy(model);
  EXPECT_TRUE(energy.prepare(g.V));
  VectorXd g0;
  SparseMatrix H;
  const EnergyTerms terms = energy.evaluate(g.V, &g0, &H, HessianKind::Exact);
  ASSERT_GT(terms.self_contact, 0.0);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(H);
  const double h = 1e-9;
  VectorXd g_fd(g0.size());
  Eigen::MatrixXd H_fd(g0.size(), g0.size());
  for (int a = 0; a < energy.free_count(); ++a)
    for (int c = 0; c < 3; ++c) {
      MatrixX3d plus = g.V, minus = g.V;
      plus(energy.free_vertices()[a], c) += h;
      minus(energy.free_vertices()[a], c) -= h;
      VectorXd gp, gm;
      const double ep = energy.evaluate(plus, &gp, nullptr, HessianKind::Exact).total();
      const double em = energy.evaluate(minus, &gm, nullptr, HessianKind::Exact).total();
      g_fd(3 * a + c) = (ep - em) / (2 * h);
      H_fd.col(3 * a + c) = (gp - gm) / (2 * h);
    }
  EXPECT_LT(relative_error(g0, g_fd), kTolerance);
  EXPECT_LT(relative_error(dense, H_fd), kTolerance);
}

} // namespace
} // namespace foldsketch
