// garment-info: panels, seams (both sides' lengths), boundary runs, mesh quality and the scene.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "cli.h"
#include "core/error.h"
#include "formats/atomic_file.h"
#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "formats/json_writer.h"
#include "formats/scene_xml.h"
#include "sim/cloth_model.h"
#include "metrics/garment_summary.h"

namespace foldsketch {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
constexpr double kMm = 1000.0;

struct SceneInfo {
  std::string path;
  Scene scene;
  std::optional<TriangleMesh> body;
  int pinned = 0;
};

std::string fmt(const char* format, auto... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

std::string human(const std::string& garment_path, const GarmentSummary& s, const Garment& g,
                  const std::optional<SceneInfo>& scene, double read_ms, double analyse_ms) {
  std::string t;
  t += fmt("garment  %s  (read %.0f ms, analysed %.0f ms)\n", garment_path.c_str(), read_ms, analyse_ms);
  t += fmt("  %d triangles, %d drape vertices, %d pattern vertices, %zu panels, %zu seams, %d stitches\n", s.triangles,
           s.drape_vertices, s.pattern_vertices, s.panels.size(), s.seams.size(), s.stitches);
  const Vector3d lo = s.drape_box.min(), hi = s.drape_box.max();
  t += fmt("  drape box [m]  x %.4f..%.4f  y %.4f..%.4f  z %.4f..%.4f\n", lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z());
  t += fmt("  quality  min angle %.2f deg (mean of per-triangle minimum %.2f deg), %zu slivers < 10 deg, %zu degenerate\n",
           s.min_angle * kDegrees, s.mean_min_angle * kDegrees, s.issues.sliver_pattern_faces.size(),
           s.issues.degenerate_pattern_faces.size());
  t += fmt("  drape vs pattern  principal stretch %.4f..%.4f\n\n", s.min_stretch, s.max_stretch);

  t += fmt("%-16s %9s %9s %11s %11s %5s  %s\n", "panel", "triangles", "vertices", "area [m2]", "drape [m2]", "loops",
           "boundary runs corner to corner [mm]");
  for (const PanelSummary& p : s.panels) {
    std::string runs;
    for (const RunSummary& r : p.runs) runs += fmt(" %.1f%s", r.length * kMm, r.closed ? "(closed)" : "");
    t += fmt("%-16s %9d %9d %11.5f %11.5f %5d %s\n", p.name.c_str(), p.triangles, p.vertices, p.area, p.drape_area, p.loops,
             runs.c_str());
  }
  t += fmt("\n%-4s %-16s %-16s %8s %13s %13s %10s %11s\n", "seam", "panel a", "panel b", "vertices", "length a [mm]",
           "length b [mm]", "diff [mm]", "drape [mm]");
  for (size_t i = 0; i < s.seams.size(); ++i) {
    const SeamSummary& m = s.seams[i];
    t += fmt("%-4zu %-16s %-16s %8d %13.2f %13.2f %10.3f %11.2f%s\n", i + 1, g.panels[m.panel_a].name.c_str(),
             g.panels[m.panel_b].name.c_str(), m.vertices, m.length_a * kMm, m.length_b * kMm,
             (m.length_a - m.length_b) * kMm, m.drape_length * kMm, m.closed ? "  closed" : "");
  }
  if (scene) {
    const Scene& sc = scene->scene;
    const Material& mat = sc.material;
    t += fmt("\nscene  %s  (%s)\n", scene->path.c_str(), sc.name.c_str());
    if (scene->body)
      t += fmt("  body       %s  (%ld triangles, %ld vertices), contact thickness %.1f mm\n", sc.body->file.c_str(),
               static_cast<long>(scene->body->F.rows()), static_cast<long>(scene->body->V.rows()), sc.body->thickness * kMm);
    t += fmt("  material   %s: %.4g kg/m2, stretch warp %.4g weft %.4g N/m, shear %.4g N/m, Poisson %.3g, bending %.3g N m"
             " (bending length %.1f mm)\n             source: %s\n",
             mat.name.c_str(), mat.density, mat.stretch_warp, mat.stretch_weft, mat.shear, mat.poisson, mat.bending,
             mat.bending_length(sc.gravity.norm() > 0 ? sc.gravity.norm() : 9.81) * kMm, mat.source.c_str());
    t += fmt("  gravity    %g %g %g m/s2\n", sc.gravity.x(), sc.gravity.y(), sc.gravity.z());
    const auto on = [](bool b) { return b ? "on" : "off"; };
    t += fmt("  physics    body contact %s, self contact %s, friction %s, hemline %s\n", on(sc.physics.body_contact),
             on(sc.physics.self_contact), on(sc.physics.friction), on(sc.physics.hemline));
    t += fmt("  pins       %zu selectors, %d vertices pinned\n", sc.pins.size(), scene->pinned);
    t += fmt("  simulator  %s, %s preset, time step %g s, at most %d steps, tolerance %g\n", to_string(sc.simulator.mode),
             to_string(sc.simulator.preset), sc.simulator.time_step, sc.simulator.max_steps, sc.simulator.tolerance);
  }
  const auto warnings = s.issues.messages();
  if (!warnings.empty()) {
    t += "\nwarnings\n";
    for (const std::string& w : warnings) t += "  " + w + "\n";
  }
  return t;
}

std::string json(const std::string& garment_path, const GarmentSummary& s, const Garment& g,
                 const std::optional<SceneInfo>& scene, double read_ms, double analyse_ms) {
  JsonWriter j;
  j.begin_object().key("garment").value(garment_path);
  j.key("triangles").value(s.triangles).key("drape_vertices").value(s.drape_vertices);
  j.key("pattern_vertices").value(s.pattern_vertices).key("stitches").value(s.stitches);
  j.key("drape_box_m").begin_array();
  for (int d = 0; d < 3; ++d) j.value(s.drape_box.min()(d));
  for (int d = 0; d < 3; ++d) j.value(s.drape_box.max()(d));
  j.end_array();
  j.key("quality").begin_object().key("min_angle_deg").value(s.min_angle * kDegrees);
  j.key("mean_min_angle_deg").value(s.mean_min_angle * kDegrees);
  j.key("slivers").value(s.issues.sliver_pattern_faces.size()).key("degenerate").value(s.issues.degenerate_pattern_faces.size());
  j.key("flipped").value(s.issues.flipped_pattern_faces.size());
  j.key("nonmanifold_edges").value(s.issues.nonmanifold_drape_edges.size() + s.issues.nonmanifold_pattern_edges.size());
  j.key("misoriented_edges").value(s.issues.misoriented_drape_edges.size());
  j.key("min_stretch").value(s.min_stretch).key("max_stretch").value(s.max_stretch).end_object();
  j.key("panels").begin_array();
  for (const PanelSummary& p : s.panels) {
    j.begin_object().key("name").value(p.name).key("triangles").value(p.triangles).key("vertices").value(p.vertices);
    j.key("area_m2").value(p.area).key("drape_area_m2").value(p.drape_area).key("loops").value(p.loops);
    j.key("min_angle_deg").value(p.min_angle * kDegrees);
    j.key("runs_mm").begin_array();
    for (const RunSummary& r : p.runs) j.value(r.length * kMm);
    j.end_array().end_object();
  }
  j.end_array().key("seams").begin_array();
  for (const SeamSummary& m : s.seams) {
    j.begin_object().key("panel_a").value(g.panels[m.panel_a].name).key("panel_b").value(g.panels[m.panel_b].name);
    j.key("vertices").value(m.vertices).key("closed").value(m.closed);
    j.key("length_a_mm").value(m.length_a * kMm).key("length_b_mm").value(m.length_b * kMm);
    j.key("difference_mm").value((m.length_a - m.length_b) * kMm).key("drape_length_mm").value(m.drape_length * kMm);
    j.end_object();
  }
  j.end_array();
  if (scene) {
    const Scene& sc = scene->scene;
    j.key("scene").begin_object().key("file").value(scene->path).key("name").value(sc.name);
    if (scene->body)
      j.key("body").begin_object().key("file").value(sc.body->file).key("triangles").value(static_cast<long long>(scene->body->F.rows()))
          .key("thickness_m").value(sc.body->thickness).end_object();
    const Material& m = sc.material;
    j.key("material").begin_object().key("name").value(m.name).key("density_kg_m2").value(m.density);
    j.key("stretch_warp_N_m").value(m.stretch_warp).key("stretch_weft_N_m").value(m.stretch_weft).key("shear_N_m").value(m.shear);
    j.key("poisson").value(m.poisson).key("bending_N_m").value(m.bending).key("source").value(m.source).end_object();
    j.key("gravity_m_s2").begin_array().value(sc.gravity.x()).value(sc.gravity.y()).value(sc.gravity.z()).end_array();
    j.key("physics").begin_object().key("body_contact").value(sc.physics.body_contact).key("self_contact").value(sc.physics.self_contact);
    j.key("friction").value(sc.physics.friction).key("hemline").value(sc.physics.hemline).end_object();
    j.key("pinned_vertices").value(scene->pinned);
    j.key("simulator").begin_object().key("mode").value(to_string(sc.simulator.mode)).key("preset").value(to_string(sc.simulator.preset));
    j.key("time_step_s").value(sc.simulator.time_step).key("max_steps").value(sc.simulator.max_steps);
    j.key("tolerance").value(sc.simulator.tolerance).end_object().end_object();
  }
  j.key("warnings").begin_array();
  for (const std::string& w : s.issues.messages()) j.value(w);
  j.end_array();
  j.key("time_ms").begin_object().key("read").value(read_ms).key("analyse").value(analyse_ms).end_object();
  j.end_object();
  return j.str() + "\n";
}

} // namespace
} // namespace foldsketch

int main(int argc, char** argv) {
  using namespace foldsketch;
  CLI::App app{"Reads a garment OBJ (v = drape, vt = pattern, metres; an optional NAME.stitches.xml beside it)\n"
               "or a scene.xml (then also its body and settings) and prints panels, seams with both sides'\n"
               "lengths [mm], boundary runs between corners [mm], mesh quality and the scene's physics.\n"
               "A table for people by default, one line of JSON with --json.",
               "garment-info"};
  std::string input, output = "-";
  bool as_json = false;
  app.add_option("input", input, "garment OBJ or scene XML")->required();
  app.add_flag("--json", as_json, "print one line of JSON");
  app.add_option("-o,--output", output, "where to write the report ('-' = standard output)")->capture_default_str();
  return run_tool(app, argc, argv, [&] {
    const auto start = std::chrono::steady_clock::now();
    std::optional<SceneInfo> scene;
    std::string garment_path = input;
    if (std::filesystem::path(input).extension() == ".xml") {
      scene = SceneInfo{input, read_scene_xml(input), std::nullopt, 0};
      garment_path = scene_relative(input, scene->scene.garment_file);
      if (scene->scene.body) scene->body = read_body_mesh(scene_relative(input, scene->scene.body->file));
    }
    const Garment g = read_garment(garment_path);
    if (scene) {
      try {
        scene->pinned = static_cast<int>(pinned_vertices(scene->scene, g.V).size());
      } catch (const ArgumentError& e) {
        throw InputError(input, 0, e.what());
      }
    }
    const double read_ms = elapsed_ms(start);
    const auto analyse_start = std::chrono::steady_clock::now();
    const GarmentSummary summary = garment_summary(g);
    const double analyse_ms = elapsed_ms(analyse_start);
    const std::string text = as_json ? json(garment_path, summary, g, scene, read_ms, analyse_ms)
                                     : human(garment_path, summary, g, scene, read_ms, analyse_ms);
    write_file_atomically(output, [&](std::ostream& out) { out << text; });
  });
}
