// Drape benchmark: the skirt sample at several sizes, each solver preset against a reference
// drape solved at a tight tolerance. Prints a table (median of --runs runs) and writes a CSV
// for plot_drape.gp. Not a test: timings depend on the machine.
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
  app.add_option("--sizes", sizes, "target triangle counts")->delimiter(',');
  app.add_option("--runs", runs, "runs per preset (the median is reported)")->check(CLI::PositiveNumber);
  app.add_option("--body", body_path, "body mesh");
  app.add_option("--csv", csv_path, "CSV to write");
  CLI11_PARSE(app, argc, argv);

  const TriangleMesh body = read_body_mesh(body_path);
  std::ofstream csv(csv_path);
  csv << "triangles,preset,median_s,newton_iterations,factorizations,factorization_share,residual,mean_error_mm,max_error_mm,converged\n";
  std::printf("%9s %-9s %10s %7s %8s %8s %9s %10s %10s\n", "triangles", "preset", "median [s]", "Newton", "factor.", "factor.%",
              "residual", "mean [mm]", "max [mm]");
  for (int size : sizes) {
    SampleParams params;
    params.triangles = size;
    SampleScene sample = make_sample("skirt", params, &body.V);
    sample.scene.body = BodySettings{"body"};
    const std::vector<int> pinned = pinned_vertices(sample.scene, sample.garment.V);
    const ClothModel model = cloth_model(sample.garment, sample.scene, &body, pinned);
    DrapeSettings reference_settings;
    reference_settings.tolerance = 1e-9;
    reference_settings.max_steps = 20000;
    const DrapeResult reference = solve_drape(model, sample.garment.V, reference_settings);
    for (const SolverPreset preset : {SolverPreset::Accurate, SolverPreset::Fast}) {
      DrapeSettings settings;
      settings.preset = preset;
      settings.max_steps = 20000;
      std::vector<double> seconds;
      DrapeResult result;
      for (int r = 0; r < runs; ++r) {
        result = solve_drape(model, sample.garment.V, settings);
        seconds.push_back(result.stats.seconds_total);
      }
      const VectorXd distance = (result.V - reference.V).rowwise().norm();
      const DrapeStats& s = result.stats;
      const double share = s.seconds_factorization / s.seconds_total;
      std::printf("%9ld %-9s %10.2f %7d %8d %7.0f%% %9.2e %10.3f %10.3f%s\n", static_cast<long>(model.triangles.size()),
                  to_string(preset), median(seconds), s.newton_iterations, s.factorizations, 100 * share, s.residual,
                  1000 * distance.mean(), 1000 * distance.maxCoeff(), s.converged ? "" : "  (not converged)");
      std::fflush(stdout);
      csv << model.triangles.size() << ',' << to_string(preset) << ',' << median(seconds) << ',' << s.newton_iterations << ','
          << s.factorizations << ',' << share << ',' << s.residual << ',' << 1000 * distance.mean() << ','
          << 1000 * distance.maxCoeff() << ',' << (s.converged ? 1 : 0) << '\n';
    }
    std::printf("%9s reference: %d Newton iterations, residual %.2e%s\n", "", reference.stats.newton_iterations,
                reference.stats.residual, reference.stats.converged ? "" : " (not converged)");
  }
  return 0;
}
