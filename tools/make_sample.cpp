// make-sample: writes a sample scene (garment, body, scene.xml) at any resolution.
#include <filesystem>
#include <iostream>

#include "cli.h"
#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "formats/json_writer.h"
#include "formats/scene_xml.h"
#include "garment/seams.h"
#include "samples/sample_scenes.h"

int main(int argc, char** argv) {
  using namespace foldsketch;
  CLI::App app{"Writes a sample scene into folder DIR: DIR/garment.obj (drape and patterns in metres),\n"
               "DIR/scene.xml, and for generated obstacles DIR/body.obj. Samples: flag, skirt, box-cover,\n"
               "dress. skirt and dress are fitted around --body (a human mesh in metres, y up, facing +z);\n"
               "the scene refers to that file by a path relative to DIR. The drape is the sewn placement.",
               "make-sample"};
  std::string name, folder, body_path;
  SampleParams params;
  bool json = false;
  app.add_option("name", name, "sample name")->required()->check(CLI::IsMember(sample_names()));
  app.add_option("-o,--output", folder, "folder to write (created if missing)")->required();
  app.add_option("--triangles", params.triangles, "target triangle count (result within a few %)")
      ->capture_default_str()->check(CLI::Range(50, 2000000));
  std::string mesh = "grid";
  app.add_option("--mesh", mesh, "grid (structured) or isotropic (better for bending)")->capture_default_str()
      ->check(CLI::IsMember({"grid", "isotropic"}));
  app.add_option("--body", body_path, "body mesh for skirt and dress (OBJ, PLY, STL, glTF; metres)");
  app.add_flag("--json", json, "print a one-line JSON summary");
  return run_tool(app, argc, argv, [&] {
    const auto start = std::chrono::steady_clock::now();
    params.mesh = mesh == "isotropic" ? SampleMesh::Isotropic : SampleMesh::Grid;
    std::optional<TriangleMesh> body;
    if (sample_needs_body(name)) {
      if (body_path.empty()) throw std::runtime_error("sample '" + name + "' needs --body");
      body = read_body_mesh(body_path);
    }
    SampleScene sample = make_sample(name, params, body ? &body->V : nullptr);
    std::filesystem::create_directories(folder);
    sample.scene.garment_file = "garment.obj";
    if (sample.body) {
      sample.scene.body = BodySettings{"body.obj"};
      write_mesh_obj(*sample.body, (std::filesystem::path(folder) / "body.obj").string());
    } else if (body) {
      const auto relative = std::filesystem::relative(std::filesystem::absolute(body_path), std::filesystem::absolute(folder));
      sample.scene.body = BodySettings{relative.generic_string()};
    }
    write_garment(sample.garment, (std::filesystem::path(folder) / "garment.obj").string());
    write_scene_xml(sample.scene, (std::filesystem::path(folder) / "scene.xml").string());
    const size_t seam_count = seams(sample.garment, panel_boundaries(sample.garment)).size();
    const double ms = elapsed_ms(start);
    if (json) {
      JsonWriter j;
      j.begin_object().key("sample").value(name).key("folder").value(folder);
      j.key("triangles").value(static_cast<long long>(sample.garment.F.rows()));
      j.key("panels").value(sample.garment.panels.size()).key("seams").value(seam_count);
      j.key("time_ms").value(ms).end_object();
      std::cout << j.str() << "\n";
    } else {
      std::cout << "make-sample: wrote " << folder << "/ (" << name << ": " << sample.garment.F.rows() << " triangles, "
                << sample.garment.panels.size() << " panels, " << seam_count << " seams) in " << static_cast<int>(ms) << " ms\n";
    }
  });
}
