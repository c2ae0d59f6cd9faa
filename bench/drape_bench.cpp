// Drape benchmark: the skirt sample at several sizes, each solver preset against a reference
// drape solved at a tight tolerance. Prints a table (median of --runs runs) and writes a CSV
// for plot_drape.gp. Not a test: timings depend on the machine.
//
// Two starts: "cold", from the sample's sewn placement (the folds form from nothing), and
// "warm", the pipeline's case: the patterns change a little (here they widen by --ease, as when
// update-patterns adds ease) and the garment re-drapes from the previous equilibrium.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include <CLI/CLI.hpp>

#include "formats/body_mesh.h"
#include "samples/sample_scenes.h"
#include "sim/drape_solver.h"

using namespace foldsketch;

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
} // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times drape-free's solver presets on the skirt sample at several sizes and measures their error\n"
               "(mean and max vertex distance, mm) against a reference drape solved at tolerance 1e-9.",
               "drape_bench"};
  std::vector<int> sizes{5000, 10000, 20000, 54000};
  int runs = 3;
  std::string body_path = "samples/bodies/mean_all.obj", csv_path = "bench/drape_bench.csv";
  std::string warm_csv_path = "bench/drape_bench_warm.csv";
  std::vector<std::string> starts{"cold", "warm"};
  std::vector<std::string> presets{"accurate", "fast"};
  double ease = 0.02;
  bool trace = false;
  double time_step = DrapeSettings{}.time_step;
  app.add_option("--sizes", sizes, "target triangle counts")->delimiter(',');
  app.add_option("--runs", runs, "runs per preset (the median is reported)")->check(CLI::PositiveNumber);
  app.add_option("--body", body_path, "body mesh");
  app.add_option("--csv", csv_path, "CSV to write (cold starts)");
  app.add_option("--warm-csv", warm_csv_path, "CSV to write (warm starts)");
  app.add_option("--starts", starts, "cold (from the sewn placement), warm (re-drape after the patterns widen)")
      ->delimiter(',')
      ->check(CLI::IsMember({"cold", "warm"}));
  app.add_option("--presets", presets, "solver presets to time")->delimiter(',')->check(CLI::IsMember({"accurate", "fast"}));
  app.add_option("--ease", ease, "warm start: relative widening of every pattern (pattern x)")->check(CLI::PositiveNumber);
  app.add_option("--time-step", time_step, "first quasi-static step [s]: the solver's damping starts at 1/h^2")
      ->check(CLI::PositiveNumber);
  app.add_flag("--trace", trace,
               "print every Newton iteration of the timed solves on stderr (factorisations so far, residual, step, damping)");
  CLI11_PARSE(app, argc, argv);
  const DrapeProgress tracer = [](const DrapeStats& s) {
    std::fprintf(stderr, "%5d factorisations %5d residual %.3e step %.3f length %.2e damping %.1e\n", s.newton_iterations,
                 s.factorizations, s.residual, s.step_fraction, s.step_length, s.damping);
  };

  const TriangleMesh body = read_body_mesh(body_path);
  const bool cold = std::find(starts.begin(), starts.end(), "cold") != starts.end();
  const bool warm = std::find(starts.begin(), starts.end(), "warm") != starts.end();
  const char* header = "triangles,preset,median_s,newton_iterations,factorizations,factorization_share,residual,mean_error_mm,max_error_mm,converged\n";
  std::ofstream csv, warm_csv;
  if (cold) (csv.open(csv_path), csv << header);
  if (warm) (warm_csv.open(warm_csv_path), warm_csv << header);
  const auto table_header = [](const char* title) {
    std::printf("%s\n%9s %-9s %10s %7s %8s %8s %9s %10s %10s\n", title, "triangles", "preset", "median [s]", "Newton", "factor.",
                "factor.%", "residual", "mean [mm]", "max [mm]");
  };
  // Both presets from `start`, each timed `runs` times, against `reference`.
  const auto time_presets = [&](const ClothModel& model, const MatrixX3d& start, const DrapeResult& reference, std::ofstream& out) {
    for (const SolverPreset preset : {SolverPreset::Accurate, SolverPreset::Fast}) {
      if (std::find(presets.begin(), presets.end(), to_string(preset)) == presets.end()) continue;
      DrapeSettings settings;
      settings.preset = preset;
      settings.max_steps = 20000;
      settings.time_step = time_step;
      std::vector<double> seconds;
      DrapeResult result;
      for (int r = 0; r < runs; ++r) {
        result = solve_drape(model, start, settings, trace ? tracer : DrapeProgress{});
        seconds.push_back(result.stats.seconds_total);
      }
      const VectorXd distance = (result.V - reference.V).rowwise().norm();
      const DrapeStats& s = result.stats;
      const double share = s.seconds_factorization / s.seconds_total;
      std::printf("%9ld %-9s %10.2f %7d %8d %7.0f%% %9.2e %10.3f %10.3f%s\n", static_cast<long>(model.triangles.size()),
                  to_string(preset), median(seconds), s.newton_iterations, s.factorizations, 100 * share, s.residual,
                  1000 * distance.mean(), 1000 * distance.maxCoeff(), s.converged ? "" : "  (not converged)");
      std::fflush(stdout);
      out << model.triangles.size() << ',' << to_string(preset) << ',' << median(seconds) << ',' << s.newton_iterations << ','
          << s.factorizations << ',' << share << ',' << s.residual << ',' << 1000 * distance.mean() << ','
          << 1000 * distance.maxCoeff() << ',' << (s.converged ? 1 : 0) << '\n';
    }
    std::printf("%9s reference: %d Newton iterations, residual %.2e%s\n", "", reference.stats.newton_iterations,
                reference.stats.residual, reference.stats.converged ? "" : " (not converged)");
  };
  DrapeSettings reference_settings;
  reference_settings.tolerance = 1e-9;
  reference_settings.max_steps = 20000;
  for (int size : sizes) {
    SampleParams params;
    params.triangles = size;
    SampleScene sample = make_sample("skirt", params, &body.V);
    sample.scene.body = BodySettings{"body"};
    const std::vector<int> pinned = pinned_vertices(sample.scene, sample.garment.V);
    const ClothModel model = cloth_model(sample.garment, sample.scene, &body, pinned);
    const DrapeResult reference = solve_drape(model, sample.garment.V, reference_settings);
    if (cold) {
      table_header("cold start: from the sewn placement");
      time_presets(model, sample.garment.V, reference, csv);
    }
    if (warm) {
      Garment wider = sample.garment;
      wider.P.col(0) *= 1.0 + ease;
      const ClothModel wider_model = cloth_model(wider, sample.scene, &body, pinned);
      const DrapeResult wider_reference = solve_drape(wider_model, reference.V, reference_settings);
      char title[160];
      std::snprintf(title, sizeof title, "warm start: patterns %.0f %% wider, from the previous drape (the cold reference)", 100 * ease);
      table_header(title);
      time_presets(wider_model, reference.V, wider_reference, warm_csv);
    }
  }
  return 0;
}
