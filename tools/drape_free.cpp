// drape-free: plain cloth simulation from patterns and an initial drape to equilibrium.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <unistd.h>

#include "cli.h"
#include "core/error.h"
#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "formats/json_writer.h"
#include "formats/scene_xml.h"
#include "garment/drape_scale.h"
#include "garment/pins.h"
#include "sim/coarse_to_fine.h"
#include "sim/drape_solver.h"
#include "sim/pattern_change.h"

namespace foldsketch {
namespace {

HessianKind hessian_kind(const std::string& name) {
  return name == "exact" ? HessianKind::Exact : name == "projected" ? HessianKind::Projected : HessianKind::GaussNewton;
}

// "; closest cloth-cloth approach 0.812 mm (self-contact on 1200 vertices)" under
// self-contact, else nothing.
std::string self_contact_text(const DrapeStats& s, int self_vertices) {
  if (std::isnan(s.min_self_distance)) return "";
  char text[120];
  std::snprintf(text, sizeof text, "; closest cloth-cloth approach %.3f mm (self-contact on %d vertices)", 1000 * s.min_self_distance,
                self_vertices);
  return text;
}

// "a stable equilibrium", with the saddles left on the way when there were any.
std::string stability_text(const DrapeStats& s) {
  std::string text = s.stability == Stability::Stable     ? "a stable equilibrium"
                     : s.stability == Stability::Unstable ? "an UNSTABLE equilibrium"
                                                          : "stability not checked";
  if (s.saddle_escapes > 0)
    text += " (after leaving " + std::to_string(s.saddle_escapes) + (s.saddle_escapes > 1 ? " saddles)" : " saddle)");
  return text;
}

// self_vertices: drape vertices under self-contact, -1 without it.
std::string human(const DrapeStats& s, double tolerance, int self_vertices) {
  char line[1024];
  std::snprintf(line, sizeof line,
                "drape-free: %s: %d steps, %d Newton iterations (%d with projected membrane elements), %d factorisations; relative force residual %.2e "
                "(tolerance %.0e, 2-norm over free vertices / weight); max strain %.3f %%; deepest body penetration "
                "%.3f mm%s; %s\ndrape-free: time %.2f s (assembly %.2f, factorisation %.2f, solve %.2f, curved steps %.2f, line search %.2f)\n",
                s.message.c_str(), s.steps, s.newton_iterations, s.projected_iterations, s.factorizations, s.residual, tolerance, 100 * s.max_strain,
                1000 * s.max_penetration, self_contact_text(s, self_vertices).c_str(), stability_text(s).c_str(), s.seconds_total, s.seconds_assembly, s.seconds_factorization,
                s.seconds_solve, s.seconds_curvature, s.seconds_line_search);
  return line;
}

// The pattern-change predictor's line, when it was tried.
std::string predictor_text(const std::optional<PatternChangeStep>& p) {
  if (!p) return "";
  char line[400];
  if (p->applied)
    std::snprintf(line, sizeof line,
                  "drape-free: the initial drape's patterns differ: predicted its response first (%.3g of the step, largest "
                  "move %.2f mm, %.2f s)\n", p->step_fraction, 1000 * p->step_length, p->seconds);
  else
    std::snprintf(line, sizeof line, "drape-free: the initial drape's patterns differ, no prediction: %s\n", p->message.c_str());
  return line;
}

// One line per level of a coarse-to-fine drape (none for a plain drape).
std::string levels_text(const std::vector<DrapeLevel>& levels) {
  std::string out;
  for (size_t k = 0; k < levels.size(); ++k) {
    const DrapeStats& s = levels[k].stats;
    char line[300];
    std::snprintf(line, sizeof line, "drape-free: level %zu of %zu, %d triangles: %s: %d Newton iterations, %d factorisations, %.2f s\n",
                  k + 1, levels.size(), levels[k].triangles, s.message.c_str(), s.newton_iterations, s.factorizations, s.seconds_total);
    out += line;
  }
  return out;
}

// The budget's line, when the Fast preset's re-drape budget ended the solve: how far the drape
// moved, the only distance known without the equilibrium. moved: mean vertex distance from the
// solve's start [m].
std::string budget_text(const DrapeStats& s, double moved) {
  if (!s.stopped_at_budget) return "";
  char line[500];
  std::snprintf(line, sizeof line,
                "drape-free: fast preset on a re-drape: stopped at its budget, %.3f mm mean from its start; not an "
                "equilibrium (on the benchmark skirt's re-drapes from equilibria 0.3-0.8 of the predicted start's distance "
                "to it was left, median 0.5: bench/README.md); --preset accurate drapes to equilibrium\n", 1000 * moved);
  return line;
}

// levels: the levels of a coarse-to-fine drape (empty for a plain drape); s is the last
// level's, but for the total time. moved: see budget_text.
std::string json(const DrapeStats& s, double tolerance, const std::string& output, bool written, int self_vertices,
                 const std::vector<DrapeLevel>& levels, const std::optional<PatternChangeStep>& predictor, double moved) {
  JsonWriter j;
  j.begin_object().key("converged").value(s.converged).key("stopped_at_budget").value(s.stopped_at_budget);
  j.key("message").value(s.message).key("stability").value(to_string(s.stability));
  j.key("saddle_escapes").value(s.saddle_escapes);
  if (s.stability == Stability::Unstable) j.key("lowest_curvature_per_s2").value(s.lowest_curvature);
  j.key("moved_mean_m").value(moved);
  j.key("output").value(written ? output : "").key("steps").value(s.steps).key("newton_iterations").value(s.newton_iterations);
  j.key("projected_iterations").value(s.projected_iterations);
  j.key("factorizations").value(s.factorizations).key("double_precision_fallback").value(s.double_precision_fallback);
  j.key("rescue_iterations").value(s.rescue_iterations).key("indefinite_solves").value(s.indefinite_solves);
  j.key("residual").value(s.residual).key("tolerance").value(tolerance);
  j.key("energy_J").begin_object().key("membrane").value(s.energy.membrane).key("bending").value(s.energy.bending);
  j.key("gravity").value(s.energy.gravity).key("stitches").value(s.energy.stitches).key("contact").value(s.energy.contact);
  j.key("self_contact").value(s.energy.self_contact).end_object();
  j.key("max_strain").value(s.max_strain).key("max_penetration_m").value(s.max_penetration);
  if (!std::isnan(s.min_self_distance)) j.key("min_self_distance_m").value(s.min_self_distance);
  if (self_vertices >= 0) j.key("self_contact_vertices").value(self_vertices);
  j.key("time_s").begin_object().key("assembly").value(s.seconds_assembly).key("factorization").value(s.seconds_factorization);
  j.key("solve").value(s.seconds_solve).key("curved_steps").value(s.seconds_curvature).key("line_search").value(s.seconds_line_search).key("total").value(s.seconds_total).end_object();
  if (predictor) {
    j.key("predictor").begin_object().key("applied").value(predictor->applied).key("message").value(predictor->message);
    j.key("step_fraction").value(predictor->step_fraction).key("largest_move_m").value(predictor->step_length);
    j.key("time_s").value(predictor->seconds).end_object();
  }
  if (!levels.empty()) {
    j.key("levels").begin_array();
    for (const DrapeLevel& l : levels)
      j.begin_object().key("triangles").value(l.triangles).key("converged").value(l.stats.converged).key("newton_iterations")
          .value(l.stats.newton_iterations).key("factorizations").value(l.stats.factorizations).key("residual").value(l.stats.residual)
          .key("time_s").value(l.stats.seconds_total).end_object();
    j.end_array();
  }
  j.end_object();
  return j.str() + "\n";
}

} // namespace
} // namespace foldsketch

int main(int argc, char** argv) {
  foldsketch::restart_with_huge_pages(argv);
  using namespace foldsketch;
  CLI::App app{"Reads a scene.xml (garment, body, material, pins, solver settings), takes the rest shape from the\n"
               "patterns (vt of --patterns, default the scene's garment) and the start from an initial drape\n"
               "(v of --init, default the same garment), simulates the cloth alone to equilibrium and writes the\n"
               "garment OBJ with the equilibrium drape (metres). Reports steps, Newton iterations, factorisations,\n"
               "relative force residual, max strain, deepest body penetration and time per phase.\n"
               "Patterns and drape are both in metres: a drape on median more than 3 times larger or smaller\n"
               "than its patterns (patterns in mm or cm, texture coordinates in vt) is refused. Warns when the\n"
               "pins hold an edge more than 1.5 times its pattern length.\n"
               "A converged static drape is checked to be a stable equilibrium (the Hessian positive definite up to\n"
               "0.01 s^-2 times the mass); from a saddle (a symmetric start, a sheet squeezed flat) it goes on along the\n"
               "softest mode, and says so when it cannot leave one (a warning; the drape is still written).\n"
               "Exit 1 when it does not converge (nothing written unless --write-unconverged); the fast preset's\n"
               "re-drape, stopped after its 20 Newton iterations as asked, is written (exit 0).",
               "drape-free"};
  std::string scene_path, patterns_path, init_path, output;
  std::string preset;
  double tolerance = 0;
  int max_steps = 0;
  bool as_json = false, write_unconverged = false, trace = false;
  app.add_option("scene", scene_path, "scene XML")->required();
  app.add_option("--patterns", patterns_path, "garment OBJ whose vt are the rest shape (default: the scene's garment)");
  app.add_option("--init", init_path,
                 "garment OBJ whose v are the initial drape (default: the patterns file). When its vt differ from the "
                 "patterns' (a re-drape after a pattern change) and the drape is an equilibrium of them, the solve starts "
                 "from the drape's first-order response to the change (lib/sim/pattern_change.h; 12 % fewer Newton "
                 "iterations over the benchmark's re-drapes of the grid skirt, 28 % on the samples' isotropic mesh; with "
                 "self-contact, no layer passes another on the way)");
  app.add_option("-o,--output", output, "garment OBJ to write")->required();
  app.add_option("--preset", preset,
                 "solver preset, overriding the scene. accurate: to the tolerance. fast: to 100 times the tolerance; on a "
                 "re-drape (--init a drape of other patterns whose forces under them are under a tenth of those the change "
                 "adds: an equilibrium, or a drape the fast preset stopped) it stops after 20 Newton iterations at the "
                 "latest and writes that drape, which is not an equilibrium: on the benchmark skirt's re-drapes from "
                 "equilibria (bench/README.md) 0.3-0.8 of the predicted start's distance to the equilibrium was left "
                 "(median 0.5), e.g. 1.3-1.9 mm mean in 2.1-2.3 s at 20K triangles with the patterns 5 % wider")
      ->check(CLI::IsMember({"accurate", "fast"}));
  app.add_option("--tolerance", tolerance, "relative force residual, overriding the scene")->check(CLI::PositiveNumber);
  app.add_option("--max-steps", max_steps, "iterations or time steps, overriding the scene")->check(CLI::PositiveNumber);
  app.add_flag("--json", as_json, "print one line of JSON");
  app.add_flag("--trace", trace, "print every iteration on standard error");
  std::string bending_hessian;
  app.add_option("--bending-hessian", bending_hessian, "accurate preset's hinge Hessian (for measurements)")
      ->check(CLI::IsMember({"projected", "gauss-newton", "exact"}));
  bool straight_steps = false;
  app.add_flag("--straight-steps", straight_steps,
               "line-search along the straight Newton step instead of the curved one (for measurements)");
  bool plain_metric = false;
  app.add_flag("--plain-metric", plain_metric,
               "damp the static steps by the pattern's plain Laplacian instead of one weighted by each triangle's "
               "compressive stress (DrapeSettings::stress_metric_reference; for measurements)");
  std::string membrane_hessian;
  app.add_option("--membrane-hessian", membrane_hessian, "accurate preset's triangle Hessian (for measurements)")
      ->check(CLI::IsMember({"projected", "gauss-newton", "exact"}));
  app.add_flag("--write-unconverged", write_unconverged, "write the drape even when it did not converge");
  bool no_rescue = false;
  app.add_flag("--no-rescue", no_rescue,
               "take a single-precision solve that one refinement leaves inaccurate as a reason to factorise in double "
               "precision from there on, without first trying conjugate gradients preconditioned by the factor "
               "(DrapeSettings::rescue_iterations; for measurements)");
  bool no_predictor = false;
  app.add_flag("--no-predictor", no_predictor, "start from --init as it is, even when its patterns differ (for measurements)");
  bool coarse_to_fine = false;
  std::vector<int> coarse_levels_asked;
  CLI::Option* levels_option =
      app.add_option("--coarse-levels", coarse_levels_asked,
                     "drape coarse to fine through the patterns remeshed at these triangle counts (comma-separated, "
                     "coarsest first), then the garment's own mesh from the last of them")
          ->allow_extra_args(false)  // one comma-separated list, so the scene after it stays positional
          ->delimiter(',')
          ->check(CLI::PositiveNumber);
  app.add_flag("--coarse-to-fine", coarse_to_fine,
               "for a cold drape (from a placement): drape the patterns remeshed coarser first (a quarter of the "
               "triangles per level, none under 2000), each level from the one before, the garment's own mesh last. "
               "Measured on the benchmark skirt (bench/drape_bench.txt): on the samples' isotropic meshing 1.6 and "
               "2.8 times faster at 10K and 20K triangles, as fast at 54K (one path); on a grid mesh 1.5 times "
               "faster at 20K but 3.1 times slower at 10K and 54K. It ends in another "
               "equilibrium, with other folds, than the plain drape (16 and 9 mm mean apart on the isotropic skirt "
               "at 10K and 20K; a start moved by 1 um alone ends the plain drape 0.6-2.9 and 6-13 mm away), and it "
               "depends far less on its start: from starts moved by 1 um its drapes ended 0.004-0.07 mm mean apart "
               "(once 1.5 mm) on the 10K and 20K skirts (bench/cold_paths.sh). Meant for cold drapes: on a "
               "re-drape the coarse levels blur the start's folds; after a large change (a 20 % flare let into "
               "each panel, drape_bench --flare) it was 1.0-2.5 times faster than the plain re-drape on the grid "
               "skirt at 20K triangles, 0.7-1.2 times at 10K and 0.8-1.1 times on the isotropic skirt. Not with "
               "self-contact or explicit stitches")
      ->excludes(levels_option);
  return run_tool(app, argc, argv, [&] {
    const Scene scene = read_scene_xml(scene_path);
    if (patterns_path.empty()) patterns_path = scene_relative(scene_path, scene.garment_file);
    Garment garment = read_garment(patterns_path);
    // The initial drape's own patterns, when they are the same panels cut otherwise.
    std::optional<MatrixX2d> init_patterns;
    if (!init_path.empty()) {
      const Garment init = read_garment(init_path);
      if (init.V.rows() != garment.V.rows() || init.F != garment.F)
        throw InputError(init_path, 0, "the initial drape's mesh differs from the patterns' (" + std::to_string(init.V.rows()) +
                                           " vs " + std::to_string(garment.V.rows()) + " drape vertices)");
      garment.V = init.V;
      if (init.P.rows() == garment.P.rows() && init.FP == garment.FP && init.P != garment.P) init_patterns = init.P;
    }
    // Patterns in other units than the drape cannot drape: say so before simulating.
    if (const std::string error = drape_scale_error(garment); !error.empty())
      throw InputError(patterns_path, 0, init_path.empty() ? error : error + " (the drape: " + init_path + ")");
    std::optional<TriangleMesh> body;
    if (scene.physics.body_contact && scene.body) body = read_body_mesh(scene_relative(scene_path, scene.body->file));
    std::vector<int> pinned;
    ClothModel model;
    std::optional<ClothModel> init_model;  // the cloth under the initial drape's patterns
    try {
      pinned = pinned_vertices(scene, garment.V);
      model = cloth_model(garment, scene, body ? &*body : nullptr, pinned);
    } catch (const ArgumentError& e) {
      throw InputError(scene_path, 0, e.what());
    }
    // Pins that hold the cloth far beyond any fabric's stretch leave it no equilibrium near its
    // rest shape: say so before the solve (it may still run, to whatever end).
    if (const PinnedEdge e = most_stretched_pinned_edge(garment, pinned); e.v0 >= 0 && e.stretch > kLargestPinnedStretch)
      std::fprintf(stderr,
                   "drape-free: warning: %s: the pins hold the edge v%d-v%d at %.3g times its pattern length (more than "
                   "%.3g): the cloth between them cannot come near its rest shape; expect large strains or no convergence\n",
                   scene_path.c_str(), e.v0 + 1, e.v1 + 1, e.stretch, kLargestPinnedStretch);
    // The predictor serves static re-drapes on the garment's own mesh only.
    if (init_patterns && !no_predictor && !coarse_to_fine && coarse_levels_asked.empty() &&
        scene.simulator.mode == SimulationMode::Static) {
      Garment before = garment;
      before.P = *init_patterns;
      try {
        init_model = cloth_model_on(before, scene, model.body, pinned);
      } catch (const ArgumentError& e) {
        throw InputError(init_path, 0, std::string("its patterns: ") + e.what());
      }
    }
    DrapeSettings settings = drape_settings(scene.simulator);
    if (!preset.empty()) settings.preset = preset == "fast" ? SolverPreset::Fast : SolverPreset::Accurate;
    if (tolerance > 0) settings.tolerance = tolerance;
    if (max_steps > 0) settings.max_steps = max_steps;
    if (!bending_hessian.empty())
      settings.bending_hessian = hessian_kind(bending_hessian);
    if (!membrane_hessian.empty()) settings.membrane_hessian = hessian_kind(membrane_hessian);
    if (straight_steps) settings.curved_steps = false;
    if (plain_metric) settings.stress_metric_reference = 0.0;
    if (no_rescue) settings.rescue_iterations = 0;
    const bool terminal = ::isatty(STDERR_FILENO);
    const DrapeProgress progress = [&](const DrapeStats& s, const MatrixX3d& x) {
      if (trace)
        std::fprintf(stderr, "iteration %d residual %.3e energy %.6e step %.3g move %.3g mm damping %.3g factorisations %d time %.2f s\n",
                     s.newton_iterations, s.residual, s.energy.total(), s.step_fraction, 1000 * s.step_length, s.damping,
                     s.factorizations, s.seconds_total);
      else if (terminal)
        std::fprintf(stderr, "\rdrape-free: %ld vertices, iteration %d, residual %.2e, %.1f s   ", static_cast<long>(x.rows()),
                     s.newton_iterations, s.residual, s.seconds_total);
    };
    std::vector<DrapeLevel> levels;
    std::optional<PatternChangeStep> predictor;
    DrapeResult result;
    double moved = 0.0;  // mean vertex distance from the solve's start [m] (plain drapes; 0 for coarse-to-fine)
    if (coarse_to_fine) coarse_levels_asked = coarse_levels(static_cast<int>(model.triangles.size()));
    if (!coarse_levels_asked.empty()) {
      CoarseToFineResult c2f;
      try {
        c2f = solve_drape_coarse_to_fine(garment, scene, model, garment.V, settings, coarse_levels_asked, progress);
      } catch (const ArgumentError& e) {
        throw InputError(scene_path, 0, e.what());
      }
      result = std::move(c2f.drape);
      levels = std::move(c2f.levels);
      result.stats.seconds_total = c2f.seconds_total;  // every level's time
    } else {
      MatrixX3d start = garment.V;
      BisectedCholesky factorisation;  // the predictor's analysis is the re-drape's
      if (init_model) {
        PatternChangeSettings change;
        change.max_displacement = settings.max_displacement;
        change.factor_precision = settings.factor_precision;
        predictor = predict_pattern_change(*init_model, model, start, change, &factorisation);
        start = predictor->V;
        if (predictor->near_equilibrium) settings = redrape_settings(settings);
      }
      result = solve_drape(model, start, settings, progress, &factorisation);
      if (predictor) result.stats.seconds_total += predictor->seconds;
      moved = (result.V - start).rowwise().norm().mean();
    }
    if (terminal && !trace) std::fprintf(stderr, "\n");
    const double effective_tolerance = stopping_tolerance(settings);
    const bool write = result.stats.converged || result.stats.stopped_at_budget || write_unconverged;
    if (write) {
      garment.V = result.V;
      write_garment(garment, output);
    }
    const int self_vertices = model.self_contact ? static_cast<int>(model.self_contact->vertices.size()) : -1;
    std::cout << (as_json ? json(result.stats, effective_tolerance, output, write, self_vertices, levels, predictor, moved)
                          : predictor_text(predictor) + levels_text(levels) + human(result.stats, effective_tolerance, self_vertices) +
                                budget_text(result.stats, moved));
    if (result.stats.stability == Stability::Unstable)
      std::fprintf(stderr, "drape-free: warning: %s: %s\n", scene_path.c_str(), result.stats.message.c_str());
    if (!result.stats.converged && !result.stats.stopped_at_budget)
      throw std::runtime_error(std::string("did not converge (") + result.stats.message + ")" +
                               (write ? "; wrote the unconverged drape as asked" : "; nothing written") +
                               (result.stats.out_of_steps ? "; --max-steps (or the scene's max-steps) raises the limit" : ""));
  });
}
