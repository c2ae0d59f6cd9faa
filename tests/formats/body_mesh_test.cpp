#include "formats/body_mesh.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(BodyMesh, ObjPlyStlAndGltfGiveTheSameSolid) {
  const std::string folder = test::temp_folder();
  const TriangleMesh box = box_mesh({-0.1, 0, -0.2}, {0.3, 0.5, 0.2});
  write_mesh_obj(box, folder + "/box.obj");
  const TriangleMesh obj = read_body_mesh(folder + "/box.obj");
  EXPECT_EQ(obj.V.rows(), 8);
  EXPECT_EQ(obj.F.rows(), 12);
  EXPECT_NEAR(test::enclosed_volume(obj.V, obj.F), 0.4 * 0.5 * 0.4, 1e-6);  // assimp stores floats

  // Re-export through assimp's own writers, and read each back.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(folder + "/box.obj", 0);
  ASSERT_TRUE(scene);
  Assimp::Exporter exporter;
  for (const auto& [format, file] : {std::pair{"ply", "box.ply"}, {"stl", "box.stl"}, {"gltf2", "box.gltf"}}) {
    ASSERT_EQ(exporter.Export(scene, format, folder + "/" + file), AI_SUCCESS) << exporter.GetErrorString();
    const TriangleMesh m = read_body_mesh(folder + "/" + file);
    EXPECT_EQ(m.F.rows(), 12) << file;
    EXPECT_NEAR(test::enclosed_volume(m.V, m.F), 0.4 * 0.5 * 0.4, 1e-6) << file;
  }
}

TEST(BodyMesh, RealBodyLoadsWelded) {
  const TriangleMesh m = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  EXPECT_EQ(m.F.rows(), 47500);
  EXPECT_NEAR(m.V.col(1).maxCoeff() - m.V.col(1).minCoeff(), 1.72, 0.01);  // metres, y up
}

TEST(BodyMesh, MissingAndBrokenFilesAreReported) {
  const std::string folder = test::temp_folder();
  try {
    read_body_mesh(folder + "/none.obj");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), folder + "/none.obj: no such file");
  }
  test::write_text(folder + "/empty.obj", "# nothing\n");
  EXPECT_THROW(read_body_mesh(folder + "/empty.obj"), InputError);
}

} // namespace
} // namespace foldsketch
