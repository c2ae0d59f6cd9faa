// The committed sample drapes are equilibria: relative force residual <= 1e-6 (2-norm of the
// forces on the free vertices over the 2-norm of their weight), no vertex more than 0.5 mm
// inside the body, pinned vertices exactly where make-sample placed them; and stable (the exact
// Hessian positive definite up to kNeutralCurvature times the mass, lib/sim/stability.h).
#include <gtest/gtest.h>

#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "formats/scene_xml.h"
#include "samples/sample_scenes.h"
#include "sim/drape_solver.h"
#include "sim/stability.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

class SampleDrape : public ::testing::TestWithParam<std::string> {};

TEST_P(SampleDrape, IsAStableEquilibriumWithExactPins) {
  const std::string scene_path = test::source_path("samples/" + GetParam() + "/scene.xml");
  const Scene scene = read_scene_xml(scene_path);
  const Garment drape = read_garment(scene_relative(scene_path, scene.garment_file));
  std::optional<TriangleMesh> body;
  if (scene.body) body = read_body_mesh(scene_relative(scene_path, scene.body->file));

  // Where make-sample placed the garment, and which vertices the scene pins there.
  const TriangleMesh human = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  SampleParams params;
  params.mesh = SampleMesh::Isotropic;  // as samples/regenerate.sh makes them
  const Garment placed = make_sample(GetParam(), params, &human.V).garment;
  const std::vector<int> pinned = pinned_vertices(scene, placed.V);
  EXPECT_EQ(pinned_vertices(scene, drape.V), pinned);
  for (int v : pinned) EXPECT_EQ(drape.V.row(v), placed.V.row(v)) << "pin " << v << " moved";

  const ClothModel model = cloth_model(drape, scene, body ? &*body : nullptr, pinned);
  ClothEnergy energy(model);
  VectorXd forces;
  energy.evaluate(drape.V, &forces, nullptr, HessianKind::Exact);
  const double residual = forces.norm() / energy.gravity_force().norm();
  EXPECT_LE(residual, 1e-6);
  EXPECT_LE(max_penetration(model, drape.V), 0.0005);
  const StabilityCheck stability = check_stability(energy, drape.V);
  EXPECT_TRUE(stability.stable) << "a saddle: curvature " << stability.lowest_eigenvalue << " s^-2 along its softest mode";
  RecordProperty("residual", std::to_string(residual));
  EXPECT_GT((drape.V - placed.V).norm(), 0.0) << "the committed garment is the placement, not a drape";
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleDrape, ::testing::Values("flag", "skirt", "box-cover", "dress"),
                         [](const auto& test_info) { return test_info.param == "box-cover" ? std::string("box_cover") : test_info.param; });

} // namespace
} // namespace foldsketch
