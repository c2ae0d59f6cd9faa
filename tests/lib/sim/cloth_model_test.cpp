// cloth_model and cloth_model_on: models of one garment on one body share the body's distance
// structure, and act exactly as models that built their own.
#include "sim/cloth_model.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "sim/cloth_energy.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// A re-drape's two models (the patterns 2 % wider): the second on the first's body has the same
// body contact as one built from the mesh, and holds the same structure, not a copy.
TEST(ClothModel, ModelsOfOneGarmentShareTheBody) {
  const test::SkirtOnBody s = test::skirt_on_body(1000);
  ASSERT_TRUE(s.model.body);
  Garment wider = s.skirt.garment;
  wider.P.col(0) *= 1.02;
  const ClothModel shared = cloth_model_on(wider, s.skirt.scene, s.model.body, s.pinned);
  EXPECT_EQ(shared.body.get(), s.model.body.get());
  const TriangleMesh human = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  const ClothModel own = cloth_model(wider, s.skirt.scene, &human, s.pinned);
  EXPECT_NE(own.body.get(), s.model.body.get());
  // Drawn in towards the body's vertical axis (across gravity) until contact acts.
  MatrixX3d x = s.skirt.garment.V;
  const Vector3d up = -s.skirt.scene.gravity.normalized();
  const Eigen::RowVector3d centre = x.colwise().mean();
  for (int v = 0; v < x.rows(); ++v) {
    const Eigen::RowVector3d d = x.row(v) - centre;
    x.row(v) = centre + d.dot(up.transpose()) * up.transpose() + 0.8 * (d - d.dot(up.transpose()) * up.transpose());
  }
  VectorXd g_shared, g_own;
  const EnergyTerms e_shared = ClothEnergy(shared).evaluate(x, &g_shared, nullptr, HessianKind::Exact);
  const EnergyTerms e_own = ClothEnergy(own).evaluate(x, &g_own, nullptr, HessianKind::Exact);
  EXPECT_GT(e_own.contact, 0.0);
  EXPECT_EQ(e_shared.contact, e_own.contact);
  EXPECT_EQ(g_shared, g_own);
}

TEST(ClothModel, RefusesBodyContactWithoutABody) {
  const test::SkirtOnBody s = test::skirt_on_body(1000);
  EXPECT_THROW(cloth_model_on(s.skirt.garment, s.skirt.scene, nullptr, s.pinned), ArgumentError);
  EXPECT_THROW(cloth_model(s.skirt.garment, s.skirt.scene, nullptr, s.pinned), ArgumentError);
}

} // namespace
} // namespace foldsketch
