// The benchmark's stored warm starts (bench/stored_start.h): they round-trip, are refused with
// file:line on another mesh or a damaged file, and the committed ones still belong to the
// skirt meshes drape_bench builds (so a change of the sample or the mesher shows up here, not
// first in a benchmark run).
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "samples/sample_scenes.h"
#include "stored_start.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

Garment small_skirt(const TriangleMesh& body) {
  SampleParams params;
  params.triangles = 1500;
  return make_sample("skirt", params, &body.V).garment;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_all(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// The message of the InputError that reading `path` throws ("" if none).
std::string read_error(const std::string& path, Eigen::Index vertices, std::uint64_t fingerprint) {
  try {
    read_stored_start(path, vertices, fingerprint);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

class StoredStart : public ::testing::Test {
protected:
  TriangleMesh body = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  Garment skirt = small_skirt(body);
  std::string path = test::temp_folder() + "/skirt.ply";
};

TEST_F(StoredStart, RoundTripsToFloatPrecision) {
  const std::uint64_t fingerprint = mesh_fingerprint(skirt);
  write_stored_start(path, skirt.V, fingerprint, "test");
  const MatrixX3d x = read_stored_start(path, skirt.V.rows(), fingerprint);
  ASSERT_EQ(x.rows(), skirt.V.rows());
  // float keeps 24 bits: under 1e-7 relative, so under 0.2 um for a skirt within 1.5 m.
  EXPECT_LT((x - skirt.V).cwiseAbs().maxCoeff(), 2e-7);
}

TEST_F(StoredStart, FingerprintChangesWithTheMesh) {
  Garment wider = skirt;
  wider.P(0, 0) += 1e-12;
  EXPECT_NE(mesh_fingerprint(wider), mesh_fingerprint(skirt));
  Garment moved = skirt;
  moved.V(0, 1) += 1e-12;
  EXPECT_NE(mesh_fingerprint(moved), mesh_fingerprint(skirt));
  EXPECT_EQ(mesh_fingerprint(Garment(skirt)), mesh_fingerprint(skirt));
}

TEST_F(StoredStart, RefusesAnotherMeshOrADamagedFile) {
  const std::uint64_t fingerprint = mesh_fingerprint(skirt);
  write_stored_start(path, skirt.V, fingerprint, "test");
  EXPECT_NE(read_error(path, skirt.V.rows(), fingerprint + 1).find(path + ":4: the start belongs to another mesh"),
            std::string::npos);
  EXPECT_NE(read_error(path, skirt.V.rows() + 1, fingerprint).find("vertices, the mesh"), std::string::npos);
  const std::string bytes = read_all(path);
  write_all(path, bytes.substr(0, bytes.size() - 5));
  EXPECT_NE(read_error(path, skirt.V.rows(), fingerprint).find("the file ends after"), std::string::npos);
  write_all(path, bytes + "x");
  EXPECT_NE(read_error(path, skirt.V.rows(), fingerprint).find("bytes after the last vertex"), std::string::npos);
  write_all(path, "ply\nformat ascii 1.0\n");
  EXPECT_NE(read_error(path, skirt.V.rows(), fingerprint).find(path + ":2: expected 'format binary_little_endian 1.0'"),
            std::string::npos);
  EXPECT_NE(read_error(path + ".missing", skirt.V.rows(), fingerprint).find("cannot open"), std::string::npos);
}

// Every committed start (bench/starts/skirt-TRIANGLES-K.ply) belongs to the skirt mesh of that
// size, grid or isotropic (drape_bench --mesh): the sizes drape_bench's table uses.
TEST_F(StoredStart, CommittedStartsMatchTheSkirtMeshes) {
  int checked = 0;
  for (const SampleMesh mesh : {SampleMesh::Grid, SampleMesh::Isotropic}) {
    for (const int target : {5000, 10000, 20000, 54000}) {
      SampleParams params;
      params.triangles = target;
      params.mesh = mesh;
      const Garment g = make_sample("skirt", params, &body.V).garment;
      for (int k = 1; k <= 3; ++k) {
        const std::string file = stored_start_path(test::source_path("bench/starts"), static_cast<long>(g.F.rows()), k);
        SCOPED_TRACE(file);
        const MatrixX3d x = read_stored_start(file, g.V.rows(), mesh_fingerprint(g));
        EXPECT_TRUE(x.allFinite());
        // A drape, not the placement: the folds moved it.
        EXPECT_GT((x - g.V).rowwise().norm().mean(), 1e-3);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24);
}

}  // namespace
}  // namespace foldsketch
