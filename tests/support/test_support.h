// Helpers shared by the tests: hand-built garments, paths, running the real tools.
#pragma once

#include <string>
#include <vector>

#include "garment/garment.h"
#include "mesh/primitive_meshes.h"
#include "samples/sample_scenes.h"
#include "sim/cloth_model.h"

namespace foldsketch::test {

// Repository, built tools and ../shared, as configured by CMake.
std::string source_path(const std::string& relative);
std::string tool_path(const std::string& tool);
std::string shared_path(const std::string& relative);
bool shared_available();

// A fresh empty folder under the system temp folder, removed at process exit.
std::string temp_folder();

// A square panel of n x n cells of side `size` [m]; the drape is the pattern in the z = 0 plane.
Garment square_panel(int n, double size = 1.0);

// A body with one concave crease: two slopes rising `slope_degrees` from the x axis on either
// side (a V trough, faces up), 2 m square.
TriangleMesh v_trough(double slope_degrees);

// The drape vertices in g's highest row (largest y), the ones a hanging test pins.
std::vector<int> top_row(const Garment& g);

// g's cloth in thin cotton under gravity, with no body, held at `pinned`.
ClothModel cotton_model(const Garment& g, const std::vector<int>& pinned);

// The skirt sample at about `triangles` triangles in its sewn placement around the project's
// body (samples/bodies/mean_all.obj), pinned at its waist as its scene says, with its model.
struct SkirtOnBody {
  SampleScene skirt;
  std::vector<int> pinned;
  ClothModel model;
};
SkirtOnBody skirt_on_body(int triangles);

// Two unit squares side by side, sewn along their shared edge by welding: "left" and "right".
Garment two_sewn_squares();

// One flat panel meshing the polygon `outline` (counter-clockwise) minus `holes`, isotropic
// triangles of about `spacing` [m]; the drape is the pattern in the z = 0 plane.
Garment polygon_panel(const std::string& name, const MatrixX2d& outline, double spacing,
                      const std::vector<MatrixX2d>& holes = {});

// Volume enclosed by a closed triangle mesh (divergence theorem): positive iff the triangles
// face outwards.
double enclosed_volume(const MatrixX3d& V, const MatrixX3i& F);

// Result of running a command: exit status, standard output and standard error.
struct RunResult {
  int status = -1;
  std::string out, err;
};
RunResult run(const std::string& command);

std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);

} // namespace foldsketch::test
