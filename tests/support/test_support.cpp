#include "support/test_support.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "formats/body_mesh.h"
#include "mesh/isotropic_mesh.h"

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace foldsketch::test {
namespace fsys = std::filesystem;

std::string source_path(const std::string& relative) { return (fsys::path(FOLDSKETCH_SOURCE_DIR) / relative).string(); }
std::string tool_path(const std::string& tool) { return (fsys::path(FOLDSKETCH_BIN_DIR) / tool).string(); }
std::string shared_path(const std::string& relative) { return (fsys::path(FOLDSKETCH_SHARED_DIR) / relative).string(); }
bool shared_available() { return fsys::exists(shared_path("data/bgl")); }

namespace {
struct TempRoot {
  fsys::path root;
  TempRoot() {
    std::string pattern = (fsys::temp_directory_path() / "foldsketch-test-XXXXXX").string();
    root = mkdtemp(pattern.data());
  }
  // FOLDSKETCH_KEEP_TEST_FILES=1 keeps the folder, to look at what a test wrote.
  ~TempRoot() {
    if (std::getenv("FOLDSKETCH_KEEP_TEST_FILES")) {
      std::fprintf(stderr, "test files kept in %s\n", root.c_str());
      return;
    }
    std::error_code ignored;
    fsys::remove_all(root, ignored);
  }
};
} // namespace

std::string temp_folder() {
  static TempRoot root;
  static int counter = 0;
  const fsys::path folder = root.root / std::to_string(counter++);
  fsys::create_directories(folder);
  return folder.string();
}

TriangleMesh v_trough(double slope_degrees) {
  const double rise = std::tan(slope_degrees * std::numbers::pi / 180.0);
  TriangleMesh t;
  t.V.resize(6, 3);
  t.V << -1, rise, -1, 1, rise, -1, -1, 0, 0, 1, 0, 0, -1, rise, 1, 1, rise, 1;
  t.F.resize(4, 3);
  t.F << 0, 2, 1, 1, 2, 3, 2, 4, 3, 3, 4, 5;
  return t;
}

Garment square_panel(int n, double size) {
  Garment g;
  g.V.resize((n + 1) * (n + 1), 3);
  g.P.resize((n + 1) * (n + 1), 2);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      g.P.row(j * (n + 1) + i) << size * i / n, size * j / n;
      g.V.row(j * (n + 1) + i) << size * i / n, size * j / n, 0.0;
    }
  g.F.resize(2 * n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      g.F.row(2 * (j * n + i)) << a, a + 1, a + n + 2;
      g.F.row(2 * (j * n + i) + 1) << a, a + n + 2, a + n + 1;
    }
  g.FP = g.F;
  g.face_panel = VectorXi::Zero(g.F.rows());
  g.panels = {{"square"}};
  return g;
}

Garment polygon_panel(const std::string& name, const MatrixX2d& outline, double spacing,
                      const std::vector<MatrixX2d>& holes) {
  const PlanarMesh mesh = isotropic_mesh(outline, spacing, {}, holes);
  Garment g;
  g.P = mesh.P;
  g.V = MatrixX3d::Zero(mesh.P.rows(), 3);
  g.V.leftCols<2>() = mesh.P;
  g.F = mesh.F;
  g.FP = mesh.F;
  g.face_panel = VectorXi::Zero(mesh.F.rows());
  g.panels = {Panel{name}};
  return g;
}

ClothModel cotton_model(const Garment& g, const std::vector<int>& pinned) {
  Scene scene;
  scene.material = *material_preset("cotton-thin");
  scene.physics.body_contact = false;
  return cloth_model(g, scene, nullptr, pinned);
}

std::vector<int> top_row(const Garment& g) {
  std::vector<int> top;
  for (int v = 0; v < g.V.rows(); ++v)
    if (g.V(v, 1) > g.V.col(1).maxCoeff() - 1e-9) top.push_back(v);
  return top;
}

SkirtOnBody skirt_on_body(int triangles) {
  const TriangleMesh human = read_body_mesh(source_path("samples/bodies/mean_all.obj"));
  SampleParams params;
  params.triangles = triangles;
  SkirtOnBody out{make_sample("skirt", params, &human.V), {}, {}};
  out.skirt.scene.body = BodySettings{"body"};
  out.pinned = pinned_vertices(out.skirt.scene, out.skirt.garment.V);
  out.model = cloth_model(out.skirt.garment, out.skirt.scene, &human, out.pinned);
  return out;
}

Garment two_sewn_squares() {
  // Drape: a 2 x 1 strip of 6 vertices; patterns: two separate unit squares.
  Garment g;
  g.V.resize(6, 3);
  g.V << 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0;
  g.P.resize(8, 2);
  g.P << 0, 0, 1, 0, 1, 1, 0, 1,  // left panel
      3, 0, 4, 0, 4, 1, 3, 1;     // right panel, laid out apart
  g.F.resize(4, 3);
  g.F << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4;
  g.FP.resize(4, 3);
  g.FP << 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7;
  g.face_panel.resize(4);
  g.face_panel << 0, 0, 1, 1;
  g.panels = {{"left"}, {"right"}};
  return g;
}

double enclosed_volume(const MatrixX3d& V, const MatrixX3i& F) {
  double volume = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

RunResult run(const std::string& command) {
  const std::string folder = temp_folder();
  const std::string out = folder + "/stdout", err = folder + "/stderr";
  const int raw = std::system((command + " >" + out + " 2>" + err + " </dev/null").c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

} // namespace foldsketch::test
