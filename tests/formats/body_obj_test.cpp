#include "formats/body_obj.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

// What assimp makes of a file with the flags read_body_mesh used before this reader: one mesh
// per group, polygons triangulated, identical vertices joined.
TriangleMesh assimp_mesh(const std::string& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS | aiComponent_MATERIALS);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  EXPECT_TRUE(scene && scene->mNumMeshes == 1) << path;
  TriangleMesh m;
  if (!scene || scene->mNumMeshes != 1) return m;
  const aiMesh* a = scene->mMeshes[0];
  m.V.resize(a->mNumVertices, 3);
  for (unsigned v = 0; v < a->mNumVertices; ++v) m.V.row(v) << a->mVertices[v].x, a->mVertices[v].y, a->mVertices[v].z;
  m.F.resize(a->mNumFaces, 3);
  for (unsigned f = 0; f < a->mNumFaces; ++f)
    m.F.row(f) << a->mFaces[f].mIndices[0], a->mFaces[f].mIndices[1], a->mFaces[f].mIndices[2];
  return m;
}

TEST(BodyObj, ReadsTheRealBodyAsAssimpDoes) {
  const std::string path = test::source_path("samples/bodies/mean_all.obj");
  const std::optional<TriangleMesh> ours = parse_body_obj(test::read_text(path), path);
  ASSERT_TRUE(ours);
  const TriangleMesh theirs = assimp_mesh(path);
  EXPECT_EQ(ours->F, theirs.F);  // the same triangles over the same vertex numbering
  ASSERT_EQ(ours->V.rows(), theirs.V.rows());
  // Both round to single precision; assimp's own number parsing is off by an ulp at a few
  // coordinates near zero (11 of 71253, at most 7e-12 m).
  EXPECT_LT((ours->V - theirs.V).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(BodyObj, WeldsDropsUnusedVerticesAndCountsNegativeIndicesBack) {
  const std::string text =
      "# a unit square twice over, one corner written twice, one vertex unused\n"
      "mtllib none.mtl\n"
      "v 9 9 9\n"
      "v 0 0 0\n"
      "v 1 0 0\n"
      "v 1 1 0 0.5 0.5 0.5\n"  // a colour after the position
      "vt 0 0\n"
      "vn 0 0 1\n"
      "g panel\n"
      "f 2/1/1 3/1/1 4/1/1\n"
      "v 0 1 0\n"
      "v -0 0 0\n"  // the origin again, signed zero
      "usemtl cloth\n"
      "f -1//1 -3//1 -2//1   # -1: the origin again\n"
      "l 2 3\n";
  const std::optional<TriangleMesh> m = parse_body_obj(text, "square.obj");
  ASSERT_TRUE(m);
  ASSERT_EQ(m->V.rows(), 4);
  EXPECT_EQ(m->V.row(0), Eigen::RowVector3d(0, 0, 0));
  EXPECT_EQ(m->V.row(3), Eigen::RowVector3d(0, 1, 0));
  ASSERT_EQ(m->F.rows(), 2);
  EXPECT_EQ(m->F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m->F.row(1), Eigen::RowVector3i(0, 2, 3));
}

TEST(BodyObj, SplitsQuadrilateralsAsAssimpDoes) {
  const std::string folder = test::temp_folder();
  // A convex quad and a dart whose reflex corner is its fourth: the wrong diagonal would lay a
  // triangle outside the dart.
  test::write_text(folder + "/quads.obj",
                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                   "v 2 0 0\nv 4 0 0\nv 3 3 0\nv 3 1 0\n"
                   "f 1 2 3 4\nf 5 6 7 8\n");
  const std::optional<TriangleMesh> ours = parse_body_obj(test::read_text(folder + "/quads.obj"), folder + "/quads.obj");
  ASSERT_TRUE(ours);
  const TriangleMesh theirs = assimp_mesh(folder + "/quads.obj");
  EXPECT_EQ(ours->V, theirs.V);
  EXPECT_EQ(ours->F, theirs.F);
  double area = 0;
  for (int f = 2; f < 4; ++f)
    area += 0.5 * (ours->V.row(ours->F(f, 1)) - ours->V.row(ours->F(f, 0)))
                      .cross(ours->V.row(ours->F(f, 2)) - ours->V.row(ours->F(f, 0)))
                      .norm();
  EXPECT_NEAR(area, 2.0, 1e-12);  // the dart's area: 3 - 1
}

TEST(BodyObj, LeavesPolygonsToAssimp) {
  const std::string folder = test::temp_folder();
  test::write_text(folder + "/pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n");
  EXPECT_FALSE(parse_body_obj(test::read_text(folder + "/pentagon.obj"), "pentagon.obj"));
  const TriangleMesh m = read_body_mesh(folder + "/pentagon.obj");
  EXPECT_EQ(m.V.rows(), 5);
  EXPECT_EQ(m.F.rows(), 3);
}

TEST(BodyObj, ReportsTheLineOfWhatIsWrong) {
  const auto error = [](const std::string& text) {
    try {
      parse_body_obj(text, "body.obj");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("v 0 0 0\nv 1 0\n"), "body.obj:2: a vertex needs three numbers (x y z)");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 zero\n"), "body.obj:2: a vertex needs three numbers (x y z)");
  EXPECT_EQ(error("v 0 0 nan\n"), "body.obj:1: vertex 1 has a NaN or Inf coordinate");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n"), "body.obj:5: vertex index 4 is out of range (3 vertices)");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), "body.obj:4: vertex index -4 is out of range (3 vertices)");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "body.obj:4: '0' is not a vertex index");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nf 1 2\n"), "body.obj:3: a face needs at least three vertices");
  EXPECT_EQ(error("# nothing\nv 0 0 0\n"), "body.obj: the mesh has no triangles");
}

} // namespace
} // namespace foldsketch
