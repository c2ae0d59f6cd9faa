// Drape benchmark: the skirt sample at several sizes, each solver preset against a reference
// drape solved at a tight tolerance. Prints a table (median of --runs runs) and writes a CSV
// for plot_drape.gp. Not a test: timings depend on the machine.
//
// Two starts: "cold", from the sample's sewn placement (the folds form from nothing), and
// "warm", the pipeline's case: the patterns change a little (here they widen by --ease, as when
// update-patterns adds ease) and the garment re-drapes from an earlier equilibrium: each of the
// cold equilibria stored in bench/starts (stored_start.h), so that the start does not move with
// the solver under test, and the median over them. --flare replaces the widening by a flare let
// into each panel's middle (bench/pattern_flare.h): extend-patterns' kind of change, after which
// new folds form.
//
// The iteration count of a drape depends on the path its folds take, and that changes with the
// mesh: cold 20K-triangle skirts near one size took 389 to 914 Newton iterations. So the table
// ends with the cost growth fitted over all sizes (least squares in log-log), and
// --no-reference makes a sweep over many sizes affordable.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "formats/atomic_file.h"
#include "formats/body_mesh.h"
#include "samples/sample_scenes.h"
#include "sim/coarse_to_fine.h"
#include "sim/drape_solver.h"
#include "sim/pattern_change.h"
#include "cli.h"
#include "pattern_flare.h"
#include "stored_start.h"

using namespace foldsketch;

namespace {
// Mean and max distance of drape x's vertices to the reference drape's [mm].
struct ErrorMm {
  double mean = 0, max = 0;
};
ErrorMm error_mm(const MatrixX3d& x, const MatrixX3d& reference) {
  const VectorXd distance = (x - reference).rowwise().norm();
  return {1000 * distance.mean(), 1000 * distance.maxCoeff()};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Least-squares slope of log(y) against log(x): the exponent p of y ~ x^p.
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]) / n, my += std::log(y[i]) / n;
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

// The start with every vertex moved by an independent uniform random amount in
// [-amplitude, amplitude] per coordinate [m] (the solver puts pinned vertices back on their
// pins); `seed` makes it reproducible (mt19937's raw output is fixed by the standard, unlike
// its distributions).
MatrixX3d perturbed(const MatrixX3d& start, double amplitude, unsigned seed) {
  std::mt19937 random(seed);
  MatrixX3d x = start;
  for (Eigen::Index v = 0; v < x.rows(); ++v)
    for (int c = 0; c < 3; ++c) x(v, c) += amplitude * (2 * static_cast<double>(random()) / 4294967295.0 - 1);
  return x;
}

// A CSV to write at the end of a successful run (no path: not asked for, nothing written).
struct CsvFile {
  std::string path;
  std::ostringstream text;
  CsvFile(std::string to, const char* header) : path(std::move(to)) {
    if (is_open()) text << header;
  }
  bool is_open() const { return !path.empty(); }
  void write() const {
    if (is_open()) write_file_atomically(path, [&](std::ostream& out) { out << text.str(); });
  }
};

struct Row {  // one timed preset at one size, for the cost growth
  std::string start, preset;
  double triangles = 0, seconds = 0, iterations = 0;
};

// What the table prints of one preset's drape (or of the median over several starts).
struct Summary {
  double seconds = 0, iterations = 0, factorizations = 0, share = 0, residual = 0;
  bool has_error = false;  // against a reference
  ErrorMm error;
  bool converged = true;
  bool budget = false;  // stopped at the Fast preset's re-drape budget (DrapeSettings::newton_budget), as asked
};

Summary summary(const DrapeStats& s, double seconds, const std::optional<ErrorMm>& error) {
  return {seconds, static_cast<double>(s.newton_iterations), static_cast<double>(s.factorizations),
          s.seconds_factorization / s.seconds_total, s.residual, error.has_value(), error.value_or(ErrorMm{}), s.converged,
          s.stopped_at_budget};
}

// The median over starts of each column; the worst residual and max error; converged if all are.
Summary median_summary(const std::vector<Summary>& all) {
  const auto column = [&](auto field) {
    std::vector<double> v;
    for (const Summary& s : all) v.push_back(field(s));
    return v;
  };
  Summary m;
  m.seconds = median(column([](const Summary& s) { return s.seconds; }));
  m.iterations = median(column([](const Summary& s) { return s.iterations; }));
  m.factorizations = median(column([](const Summary& s) { return s.factorizations; }));
  m.share = median(column([](const Summary& s) { return s.share; }));
  const std::vector<double> residuals = column([](const Summary& s) { return s.residual; });
  m.residual = *std::max_element(residuals.begin(), residuals.end());
  m.has_error = std::all_of(all.begin(), all.end(), [](const Summary& s) { return s.has_error; });
  m.error.mean = median(column([](const Summary& s) { return s.error.mean; }));
  const std::vector<double> maxima = column([](const Summary& s) { return s.error.max; });
  m.error.max = *std::max_element(maxima.begin(), maxima.end());
  m.converged = std::all_of(all.begin(), all.end(), [](const Summary& s) { return s.converged; });
  m.budget = std::any_of(all.begin(), all.end(), [](const Summary& s) { return s.budget; });
  return m;
}

void print_row(long triangles, const std::string& label, const Summary& s) {
  char mean_error[32] = "-", max_error[32] = "-";
  if (s.has_error) {
    std::snprintf(mean_error, sizeof mean_error, "%.3f", s.error.mean);
    std::snprintf(max_error, sizeof max_error, "%.3f", s.error.max);
  }
  std::printf("%9ld %-9s %10.2f %7.0f %8.0f %7.0f%% %9.2e %10s %10s%s\n", triangles, label.c_str(), s.seconds, s.iterations,
              s.factorizations, 100 * s.share, s.residual, mean_error, max_error,
              s.converged ? "" : s.budget ? "  (budget)" : "  (not converged)");
  std::fflush(stdout);
}

// The warm start's own distance to the reference, under the presets' rows: what a solver that
// stopped at once would score, the floor against which their errors are read.
void print_start_row(long triangles, const ErrorMm& e, const char* label = "(start)") {
  std::printf("%9ld %-9s %10s %7s %8s %8s %9s %10.3f %10.3f\n", triangles, label, "-", "0", "-", "-", "-", e.mean, e.max);
  std::fflush(stdout);
}

// The stored starts for a mesh of `triangles` triangles in `folder`: K = 1, 2, ... while the
// files exist.
std::vector<std::string> stored_start_paths(const std::string& folder, long triangles) {
  std::vector<std::string> paths;
  for (int k = 1;; ++k) {
    std::string path = stored_start_path(folder, triangles, k);
    if (!std::ifstream(path)) return paths;
    paths.push_back(std::move(path));
  }
}
} // namespace

int main(int argc, char** argv) {
  foldsketch::restart_with_huge_pages(argv);  // as drape-free does: the benchmark times what users get
  CLI::App app{"Times drape-free's solver presets on the skirt sample at several sizes and measures their error\n"
               "(mean and max vertex distance, mm) against a reference drape solved at tolerance 1e-9.",
               "drape_bench"};
  std::vector<int> sizes{5000, 10000, 20000, 54000};
  int runs = 3;
  std::string body_path = "samples/bodies/mean_all.obj", csv_path, warm_csv_path;
  std::vector<std::string> starts{"cold", "warm"};
  std::vector<std::string> presets{"accurate", "fast"};
  std::string material_name;
  double ease = 0.02, flare = 0.0;
  std::string trajectory_path;
  bool trace = false, no_reference = false, straight_steps = false, no_predictor = false;
  double time_step = DrapeSettings{}.time_step;
  std::string metric = "laplacian";
  std::string factor = "single";
  double fallback_stretch = DrapeSettings{}.membrane_fallback_stretch;
  int fallback_iterations = DrapeSettings{}.membrane_fallback_iterations;
  std::vector<double> stress_metric;
  std::vector<double> perturbations;
  std::string warm_from = "bench/starts", write_starts;
  int start_count = 3;
  std::string mesh = "grid";
  std::vector<int> coarse_sizes;
  bool coarse_auto = false;
  std::string c2f_csv_path;
  app.add_option("--sizes", sizes, "target triangle counts")->delimiter(',');
  app.add_option("--runs", runs, "runs per preset (the median is reported)")->check(CLI::PositiveNumber);
  app.add_option("--body", body_path, "body mesh");
  app.add_option("--mesh", mesh, "the skirt's triangulation (make-sample --mesh): grid or isotropic")
      ->check(CLI::IsMember({"grid", "isotropic"}))
      ->capture_default_str();
  app.add_option("--csv", csv_path, "CSV to write (cold starts; bench/drape_bench.csv holds the committed rows)");
  app.add_option("--warm-csv", warm_csv_path, "CSV to write (warm starts; bench/drape_bench_warm.csv)");
  app.add_option("--starts", starts, "cold (from the sewn placement), warm (re-drape after the patterns widen)")
      ->delimiter(',')
      ->check(CLI::IsMember({"cold", "warm"}));
  app.add_option("--presets", presets, "solver presets to time")->delimiter(',')->check(CLI::IsMember({"accurate", "fast"}));
  app.add_option("--material", material_name, "fabric preset instead of the skirt sample's (thin cotton)")
      ->check(CLI::IsMember(material_preset_names()));
  CLI::Option* ease_option =
      app.add_option("--ease", ease, "warm start: relative widening of every pattern (pattern x)")->check(CLI::PositiveNumber);
  app.add_option("--flare", flare,
                 "warm start: instead of --ease, a flare let into each panel's middle half (bench/pattern_flare.h): its "
                 "width at the hem grows by this share, the outer quarters turn rigidly, the seams keep their lengths. "
                 "The pipeline's kind of change (extend-patterns adding width where hemline folds form), where new folds "
                 "must form")
      ->check(CLI::PositiveNumber)
      ->excludes(ease_option);
  app.add_option("--time-step", time_step, "first quasi-static step [s]: the solver's damping starts at 1/h^2")
      ->check(CLI::PositiveNumber);
  app.add_option("--metric", metric,
                 "what the damping of the static steps measures a step by (DrapeSettings::proximal_metric): laplacian "
                 "(the default), or mass (the quasi-static backward-Euler step), for the timed and the reference drapes")
      ->check(CLI::IsMember({"laplacian", "mass"}));
  app.add_option("--fallback-stretch", fallback_stretch,
                 "the projected-membrane fallback acts on starts with some triangle squeezed below this "
                 "(DrapeSettings::membrane_fallback_stretch; above 1: every start)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--fallback-iterations", fallback_iterations,
                 "iterations a fallback to projected membranes lasts (DrapeSettings::membrane_fallback_iterations)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--stress-metric", stress_metric,
                 "FLOOR,REFERENCE: weight each triangle's term of the Laplacian metric by FLOOR + its compressive stress "
                 "/ REFERENCE [N/m] (DrapeSettings::stress_metric_floor, stress_metric_reference)")
      ->delimiter(',')
      ->expected(2);
  app.add_flag("--no-predictor", no_predictor,
               "warm rows: start the re-drape (and its reference) from the stored start itself, not from the pattern-change "
               "predictor's step (lib/sim/pattern_change.h), as before the predictor");
  app.add_option("--factor", factor,
                 "precision of the Newton systems' factorisation (DrapeSettings::factor_precision): single (the default; "
                 "each solve refined once in double) or double (CHOLMOD's), for the timed and the reference drapes")
      ->check(CLI::IsMember({"single", "double"}))
      ->capture_default_str();
  app.add_flag("--straight-steps", straight_steps,
               "line searches along the straight Newton step, as before the curved steps (DrapeSettings::curved_steps), "
               "for the timed and the reference drapes");
  CLI::Option* no_reference_flag = app.add_flag("--no-reference", no_reference,
               "skip the reference drapes (no error columns; a warm start then starts from the cold accurate drape): "
               "for sweeps over many sizes");
  app.add_option("--trajectory", trajectory_path,
                 "CSV of the error along each timed solve: after every Newton iteration, the wall time and the mean and "
                 "max distance to the reference drape (what stopping there would cost); the table then also prints the "
                 "start's error and the time at which the error first fell to 2, 1 and 0.1 mm mean");
  app.add_option("--perturb", perturbations,
                 "also drape (accurate preset) from each start with every free vertex moved by a random amount up to "
                 "this much per coordinate [m], once per run (seeded by the run number), and report how far each ends "
                 "from the unperturbed reference and its energy against the reference's: how well the start determines "
                 "the drape, so the error columns' floor")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->excludes(no_reference_flag);
  app.add_option("--warm-from", warm_from,
                 "where the warm rows start: from each stored cold equilibrium for the size in this folder "
                 "(FOLDER/skirt-TRIANGLES-K.ply, K = 1, 2, ...; bench/starts holds the committed ones), with the median "
                 "over them in the CSV, so that the start does not change with the solver under test; 'previous', or a "
                 "size with none stored: from this run's cold reference (or cold accurate drape)");
  app.add_option("--write-starts", write_starts,
                 "write --start-count cold equilibria per size to this folder (tolerance 1e-9, from the sewn placement "
                 "moved by up to 1 um, seeds 1, 2, ...: each ends in its own fold arrangement), then stop");
  app.add_option("--start-count", start_count, "how many starts --write-starts writes per size")->check(CLI::PositiveNumber);
  CLI::Option* coarse_option =
      app.add_option("--coarse", coarse_sizes,
                     "also drape coarse to fine (drape-free --coarse-levels), through the patterns remeshed at these "
                     "triangle counts (those below the size): each level drapes (accurate preset) from the one before; "
                     "the row is the garment's own level, its time that of all levels, the median over --runs paths (run "
                     "r starts from the placement, or for a warm row from the start as it is, without the predictor, "
                     "moved by up to 1 um, seed r)")
          ->delimiter(',')
          ->check(CLI::PositiveNumber);
  app.add_flag("--coarse-to-fine", coarse_auto, "as --coarse, with the levels drape-free --coarse-to-fine picks (coarse_levels)")
      ->excludes(coarse_option);
  app.add_option("--c2f-csv", c2f_csv_path, "CSV to write of the cold coarse-to-fine rows (bench/drape_bench_c2f.csv)");
  app.add_flag("--trace", trace,
               "print every Newton iteration of the timed solves on stderr (factorisations so far, residual, step, damping)");
  CLI11_PARSE(app, argc, argv);
  std::sort(coarse_sizes.begin(), coarse_sizes.end());
  DrapeSettings defaults;  // what every drape here starts from
  defaults.proximal_metric = metric == "mass" ? ProximalMetric::Mass : ProximalMetric::Laplacian;
  defaults.curved_steps = !straight_steps;
  defaults.factor_precision = factor == "double" ? FactorPrecision::Double : FactorPrecision::Single;
  defaults.membrane_fallback_stretch = fallback_stretch;
  defaults.membrane_fallback_iterations = fallback_iterations;
  if (stress_metric.size() == 2) defaults.stress_metric_floor = stress_metric[0], defaults.stress_metric_reference = stress_metric[1];
  const DrapeProgress tracer = [](const DrapeStats& s, const MatrixX3d&) {
    std::fprintf(stderr, "%5d factorisations %5d residual %.3e step %.3f length %.2e damping %.1e\n", s.newton_iterations,
                 s.factorizations, s.residual, s.step_fraction, s.step_length, s.damping);
  };

  const bool cold = std::find(starts.begin(), starts.end(), "cold") != starts.end();
  const bool warm = std::find(starts.begin(), starts.end(), "warm") != starts.end();
  if (write_starts.empty() && warm && warm_from != "previous" && !std::filesystem::is_directory(warm_from)) {
    std::fprintf(stderr, "drape_bench: %s: no such folder of stored starts (run from the repository root, or give "
                 "--warm-from previous)\n", warm_from.c_str());
    return 1;
  }
  if (!write_starts.empty() && !std::filesystem::is_directory(write_starts)) {
    std::fprintf(stderr, "drape_bench: %s: no such folder\n", write_starts.c_str());
    return 1;
  }
  TriangleMesh body;
  try {
    body = read_body_mesh(body_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drape_bench: %s (run from the repository root, or give --body)\n", e.what());
    return 1;
  }
  // stopped_at_budget: the Fast preset's re-drape budget ended the solve (converged 0).
  const char* header = "triangles,preset,median_s,newton_iterations,factorizations,factorization_share,residual,mean_error_mm,max_error_mm,converged,stopped_at_budget\n";
  // Each CSV is collected here and written (through a temporary file and a rename) only when the
  // whole run has succeeded: a failed or interrupted run leaves the committed files as they were.
  CsvFile csv(cold ? csv_path : "", header), warm_csv(warm ? warm_csv_path : "", header);
  CsvFile trajectory(trajectory_path, "start,triangles,preset,newton_iterations,seconds,residual,mean_error_mm,max_error_mm,mean_move_mm,damping,step_fraction\n");
  std::vector<Row> rows;
  // What every timed drape (and the perturbed ones) solves with.
  const auto timed_settings = [&](SolverPreset preset) {
    DrapeSettings settings = defaults;
    settings.preset = preset;
    settings.max_steps = 20000;
    settings.time_step = time_step;
    return settings;
  };
  const auto table_header = [](const char* title) {
    std::printf("%s\n%9s %-9s %10s %7s %8s %8s %9s %10s %10s\n", title, "triangles", "preset", "median [s]", "Newton", "factor.",
                "factor.%", "residual", "mean [mm]", "max [mm]");
  };
  // One line of the CSV `out` (none: printed and fitted only) and one row of the cost growth.
  const auto record = [&](const char* start_name, long triangles, const std::string& preset, const Summary& s,
                          CsvFile* out) {
    if (out && out->is_open())
      out->text << triangles << ',' << preset << ',' << s.seconds << ',' << s.iterations << ',' << s.factorizations << ','
          << s.share << ',' << s.residual << ',' << (s.has_error ? (std::ostringstream() << s.error.mean).str() : "") << ','
          << (s.has_error ? (std::ostringstream() << s.error.max).str() : "") << ',' << (s.converged ? 1 : 0) << ','
          << (s.budget ? 1 : 0) << '\n';
    if (s.converged || s.budget) rows.push_back({start_name, preset, static_cast<double>(triangles), s.seconds, s.iterations});
  };
  // Both presets from `start`, each timed `runs` times, against `reference` (none: null); prints
  // a row per preset, and with a reference and --trajectory writes the last run's error along the solve to the
  // trajectory CSV. Returns the presets' summaries and the last accurate drape (or the last drape).
  struct Timed {
    std::vector<std::pair<std::string, Summary>> presets;
    MatrixX3d drape;
  };
  // `head_start` [s]: time spent before the solve on making `start` (the pattern-change
  // predictor's), added to every run's and every trajectory point's time. `redrape`: the start
  // is a re-drape from near an equilibrium (the predictor's force test, PatternChangeStep::
  // near_equilibrium), so the presets solve with redrape_settings, as drape-free's do.
  // `factorisation`: the predictor's, whose analysis the solves reuse as drape-free's do.
  const auto time_presets = [&](const char* start_name, const ClothModel& model, const MatrixX3d& start,
                                const DrapeResult* reference, double head_start = 0.0, bool redrape = false,
                                BisectedCholesky* factorisation = nullptr) {
    Timed timed{{}, start};
    bool have_accurate = false;
    for (const SolverPreset preset : {SolverPreset::Accurate, SolverPreset::Fast}) {
      if (std::find(presets.begin(), presets.end(), to_string(preset)) == presets.end()) continue;
      const DrapeSettings settings = redrape ? redrape_settings(timed_settings(preset)) : timed_settings(preset);
      std::vector<double> seconds;
      DrapeResult result;
      // The error along the last run, against the reference: one pass over the vertices per
      // iteration, inside the timed solve (small next to a factorisation). The first point is the
      // start (no residual: NaN).
      struct Point {
        int iterations;
        double seconds, residual;
        ErrorMm error;
        double move = 0, damping = 0, fraction = 0;  // the step's mean vertex move [mm], damping, fraction
      };
      std::vector<Point> along;
      const bool follow = reference && trajectory.is_open();
      for (int r = 0; r < runs; ++r) {
        if (follow) along.assign(1, {0, head_start, std::numeric_limits<double>::quiet_NaN(), error_mm(start, reference->V)});
        MatrixX3d previous = start;
        const bool last = r + 1 == runs;
        result = solve_drape(model, start, settings, [&](const DrapeStats& s, const MatrixX3d& x) {
          if (trace) tracer(s, x);
          if (!follow || !last) return;
          along.push_back({s.newton_iterations, head_start + s.seconds_total, s.residual, error_mm(x, reference->V),
                           error_mm(x, previous).mean, s.damping, s.step_fraction});
          previous = x;
        }, factorisation);
        seconds.push_back(head_start + result.stats.seconds_total);
      }
      std::optional<ErrorMm> error;
      if (reference) error = error_mm(result.V, reference->V);
      const Summary row = summary(result.stats, median(seconds), error);
      print_row(static_cast<long>(model.triangles.size()), to_string(preset), row);
      if (result.stats.stopped_at_budget)  // what drape-free reports of such a drape, beside its error
        std::printf("%9s %s stopped at its budget of %d Newton iterations, %.3f mm mean from its start\n", "",
                    to_string(preset), settings.newton_budget, error_mm(result.V, start).mean);
      timed.presets.emplace_back(to_string(preset), row);
      if (follow) {
        for (const Point& p : along) {
          trajectory.text << start_name << ',' << model.triangles.size() << ',' << to_string(preset) << ',' << p.iterations << ','
                     << p.seconds << ',';
          if (std::isfinite(p.residual)) trajectory.text << p.residual;
          trajectory.text << ',' << p.error.mean << ',' << p.error.max << ',' << p.move << ',' << p.damping << ',' << p.fraction << '\n';
        }
        // The first moment the error fell to each bound (it may rise again later).
        std::printf("%9s along the solve: start %.2f mm mean, %.2f mm max", "", along.front().error.mean, along.front().error.max);
        for (const double bound : {2.0, 1.0, 0.1}) {
          const auto hit = std::find_if(along.begin(), along.end(), [&](const Point& p) { return p.error.mean <= bound; });
          if (hit == along.begin()) std::printf("; <= %g mm from the start", bound);
          else if (hit != along.end()) std::printf("; <= %g mm at %.2f s (%d it.)", bound, hit->seconds, hit->iterations);
          else std::printf("; <= %g mm never", bound);
        }
        std::printf("\n");
      }
      if (preset == SolverPreset::Accurate || !have_accurate) timed.drape = result.V;
      have_accurate = have_accurate || preset == SolverPreset::Accurate;
    }
    if (reference)
      std::printf("%9s reference: %d Newton iterations, residual %.2e%s\n", "", reference->stats.newton_iterations,
                  reference->stats.residual, reference->stats.converged ? "" : " (not converged)");
    return timed;
  };
  // The accurate drape from `start` perturbed by each amplitude, `runs` seeds each, against
  // `reference`: where it ends, and at what cost.
  const auto perturb_start = [&](const ClothModel& model, const MatrixX3d& start, const DrapeResult& reference) {
    if (perturbations.empty()) return;
    std::printf("%9s from the start perturbed (accurate; per seed: Newton iterations, seconds, distance to the reference "
                "mean / max [mm], energy minus the reference's [J])\n", "");
    const DrapeSettings settings = timed_settings(SolverPreset::Accurate);
    for (const double amplitude : perturbations) {
      std::vector<double> iterations, seconds, means;
      std::printf("%9s +-%.0e m:", "", amplitude);
      for (int r = 0; r < runs; ++r) {
        const DrapeResult result = solve_drape(model, perturbed(start, amplitude, static_cast<unsigned>(r + 1)), settings);
        const ErrorMm e = error_mm(result.V, reference.V);
        std::printf("%s %d it. %.2f s %.3f / %.2f mm %+.1e J%s", r ? ";" : "", result.stats.newton_iterations,
                    result.stats.seconds_total, e.mean, e.max, result.stats.energy.total() - reference.stats.energy.total(),
                    result.stats.converged ? "" : " (not converged)");
        iterations.push_back(result.stats.newton_iterations);
        seconds.push_back(result.stats.seconds_total);
        means.push_back(e.mean);
      }
      std::printf("\n%9s   medians: %.0f it., %.2f s, %.3f mm mean\n", "", median(iterations), median(seconds), median(means));
      std::fflush(stdout);
    }
  };
  // Drapes coarse to fine (solve_drape_coarse_to_fine, as drape-free --coarse-to-fine): through
  // the garment's patterns remeshed at the --coarse triangle counts (or coarse_levels'), each
  // level draped from the one before; the row is the garment's own level, its time that of all
  // levels with the remeshing. Run r starts from `start` (the sewn placement, or a warm start as
  // it is, without the predictor) moved by up to 1 um (seed r + 1): a drape that forms folds is
  // chaotic, so each run takes its own path, and the median is over paths (no error column:
  // another path ends in another fold arrangement).
  CsvFile c2f_csv(c2f_csv_path, header);
  // Returns the row (printed here; the caller records it).
  const auto coarse_to_fine = [&](const ClothModel& model, const Garment& garment, const Scene& scene, const MatrixX3d& start) {
    const int triangles = static_cast<int>(model.triangles.size());
    std::vector<int> levels = coarse_auto ? coarse_levels(triangles) : std::vector<int>{};
    if (!coarse_auto)
      for (int level : coarse_sizes)
        if (level < triangles) levels.push_back(level);
    std::vector<double> seconds;
    std::vector<Summary> finest;
    std::string text;
    for (int r = 0; r < runs; ++r) {
      text += (r ? "\n          run " : "run ") + std::to_string(r + 1) + ":";
      const CoarseToFineResult c2f =
          solve_drape_coarse_to_fine(garment, scene, model, perturbed(start, 1e-6, static_cast<unsigned>(r + 1)),
                                     timed_settings(SolverPreset::Accurate), levels, trace ? tracer : DrapeProgress{});
      for (size_t level = 0; level < c2f.levels.size(); ++level) {
        const DrapeStats& d = c2f.levels[level].stats;
        char line[160];
        std::snprintf(line, sizeof line, "%s %d: %d it. / %d fact. %.2f s", level ? "," : "", c2f.levels[level].triangles,
                      d.newton_iterations, d.factorizations, d.seconds_total);
        text += line;
      }
      seconds.push_back(c2f.seconds_total);
      finest.push_back(summary(c2f.drape.stats, seconds.back(), std::nullopt));
    }
    Summary row = median_summary(finest);
    row.seconds = median(seconds);
    print_row(static_cast<long>(model.triangles.size()), "c2f", row);
    std::printf("%9s levels: %s\n", "", text.c_str());
    return row;
  };
  DrapeSettings reference_settings = defaults;
  reference_settings.tolerance = 1e-9;
  reference_settings.max_steps = 20000;
  for (int size : sizes) {
    SampleParams params;
    params.triangles = size;
    params.mesh = mesh == "isotropic" ? SampleMesh::Isotropic : SampleMesh::Grid;
    SampleScene sample = make_sample("skirt", params, &body.V);
    sample.scene.body = BodySettings{"body"};
    if (!material_name.empty()) sample.scene.material = *material_preset(material_name);
    const std::vector<int> pinned = pinned_vertices(sample.scene, sample.garment.V);
    const ClothModel model = cloth_model(sample.garment, sample.scene, &body, pinned);
    const long triangles = static_cast<long>(model.triangles.size());
    const std::uint64_t fingerprint = mesh_fingerprint(sample.garment);
    if (!write_starts.empty()) {
      // Cold equilibria at the reference tolerance, from the sewn placement moved by up to 1 um:
      // the cold drape is chaotic, so each seed ends in its own fold arrangement.
      constexpr double kStartPerturbation = 1e-6;  // [m]; any move does, this one is far below the mesh
      std::vector<MatrixX3d> written;
      for (int k = 1; k <= start_count; ++k) {
        const DrapeResult result =
            solve_drape(model, perturbed(sample.garment.V, kStartPerturbation, static_cast<unsigned>(k)), reference_settings);
        if (!result.stats.converged) {
          std::fprintf(stderr, "drape_bench: the cold drape of %ld triangles, seed %d, did not converge (residual %.2e)\n",
                       triangles, k, result.stats.residual);
          return 1;
        }
        const std::string path = stored_start_path(write_starts, triangles, k);
        char comment[200];
        std::snprintf(comment, sizeof comment,
                      "cold equilibrium of the skirt sample, %ld triangles: drape_bench --write-starts, seed %d, "
                      "%d Newton iterations, residual %.2e",
                      triangles, k, result.stats.newton_iterations, result.stats.residual);
        write_stored_start(path, result.V, fingerprint, comment);
        std::printf("%s: %d Newton iterations, %.2f s, residual %.2e; mean distance to the earlier starts [mm]:", path.c_str(),
                    result.stats.newton_iterations, result.stats.seconds_total, result.stats.residual);
        for (const MatrixX3d& other : written) std::printf(" %.2f", error_mm(result.V, other).mean);
        std::printf("\n");
        std::fflush(stdout);
        written.push_back(result.V);
      }
      continue;
    }
    // The warm rows' starts: the stored cold equilibria for this mesh, else this run's cold drape.
    std::vector<std::pair<std::string, MatrixX3d>> warm_starts;
    if (warm && warm_from != "previous")
      for (const std::string& path : stored_start_paths(warm_from, triangles)) try {
          warm_starts.emplace_back(path, read_stored_start(path, sample.garment.V.rows(), fingerprint));
        } catch (const std::exception& e) {
          std::fprintf(stderr, "%s\n", e.what());
          return 1;
        }
    std::optional<DrapeResult> reference;
    if (!no_reference && (cold || (warm && warm_starts.empty())))
      reference = solve_drape(model, sample.garment.V, reference_settings);
    MatrixX3d previous = reference ? reference->V : MatrixX3d();
    if (cold) {
      table_header("cold start: from the sewn placement");
      const Timed timed = time_presets("cold", model, sample.garment.V, reference ? &*reference : nullptr);
      for (const auto& [preset, row] : timed.presets) record("cold", triangles, preset, row, &csv);
      if (!reference) previous = timed.drape;
      if (reference) perturb_start(model, sample.garment.V, *reference);
      if (!coarse_sizes.empty() || coarse_auto)
        record("cold", triangles, "c2f", coarse_to_fine(model, sample.garment, sample.scene, sample.garment.V), &c2f_csv);
    }
    if (warm) {
      char change_text[80], title[280];
      if (flare > 0)
        std::snprintf(change_text, sizeof change_text, "a %.0f %% flare in each panel's middle", 100 * flare);
      else
        std::snprintf(change_text, sizeof change_text, "patterns %.0f %% wider", 100 * ease);
      if (warm_starts.empty()) {
        if (previous.rows() == 0) previous = solve_drape(model, sample.garment.V, defaults).V;
        warm_starts.emplace_back("", previous);
        std::snprintf(title, sizeof title, "warm start: %s, from the previous drape (the cold %s)", change_text,
                      reference ? "reference" : "accurate drape");
      } else {
        std::snprintf(title, sizeof title, "warm start: %s, from each of the %zu stored cold equilibria (%s/skirt-%ld-K.ply)",
                      change_text, warm_starts.size(), warm_from.c_str(), triangles);
      }
      Garment wider = sample.garment;
      if (flare > 0)
        wider = flared_patterns(sample.garment, flare);
      else
        wider.P.col(0) *= 1.0 + ease;
      const ClothModel wider_model = cloth_model_on(wider, sample.scene, model.body, pinned);
      table_header(title);
      std::vector<std::pair<std::string, std::vector<Summary>>> per_preset;  // over the starts
      std::vector<ErrorMm> start_errors;
      std::vector<Summary> c2f_rows;  // one per start
      for (size_t i = 0; i < warm_starts.size(); ++i) {
        const auto& [name, start] = warm_starts[i];
        if (!name.empty()) std::printf("%9s from %s\n", "", name.c_str());
        // The re-drape starts, as drape-free's does, from the pattern-change predictor's step
        // (lib/sim/pattern_change.h) unless --no-predictor; its time counts in every row.
        PatternChangeStep predicted;
        predicted.V = start;
        BisectedCholesky factorisation;  // the predictor's analysis, reused by the timed re-drapes
        if (!no_predictor) {
          PatternChangeSettings change;
          change.factor_precision = defaults.factor_precision;
          predicted = predict_pattern_change(model, wider_model, start, change, &factorisation);
          std::printf("%9s predictor: %s, %.3f of the step, largest move %.2f mm, %.3f s (residual %.2e, %.2e with the new "
                      "patterns)\n", "", predicted.applied ? "applied" : predicted.message.c_str(), predicted.step_fraction,
                      1e3 * predicted.step_length, predicted.seconds, predicted.start_residual, predicted.change_residual);
        }
        std::optional<DrapeResult> wider_reference;
        if (!no_reference) wider_reference = solve_drape(wider_model, predicted.V, reference_settings);
        // Every start's solves go to the trajectory CSV, as warm, warm2, warm3 (the plot draws warm).
        const std::string warm_name = i == 0 ? "warm" : "warm" + std::to_string(i + 1);
        const Timed timed = time_presets(warm_name.c_str(), wider_model, predicted.V, wider_reference ? &*wider_reference : nullptr,
                                         predicted.seconds, predicted.near_equilibrium, &factorisation);
        if (wider_reference) {
          start_errors.push_back(error_mm(start, wider_reference->V));
          print_start_row(triangles, start_errors.back());
          if (predicted.applied) print_start_row(triangles, error_mm(predicted.V, wider_reference->V), "(predict)");
        }
        for (size_t p = 0; p < timed.presets.size(); ++p) {
          if (i == 0) per_preset.emplace_back(timed.presets[p].first, std::vector<Summary>{});
          per_preset[p].second.push_back(timed.presets[p].second);
        }
        if (wider_reference) perturb_start(wider_model, predicted.V, *wider_reference);
        if (!coarse_sizes.empty() || coarse_auto) c2f_rows.push_back(coarse_to_fine(wider_model, wider, sample.scene, start));
      }
      if (warm_starts.size() > 1) std::printf("%9s median over the %zu starts (residual, max error: the worst)\n", "", warm_starts.size());
      for (const auto& [preset, all] : per_preset) {
        const Summary row = all.size() > 1 ? median_summary(all) : all.front();
        if (all.size() > 1) print_row(triangles, preset, row);
        record("warm", triangles, preset, row, &warm_csv);
      }
      if (!c2f_rows.empty()) {
        const Summary row = c2f_rows.size() > 1 ? median_summary(c2f_rows) : c2f_rows.front();
        if (c2f_rows.size() > 1) print_row(triangles, "c2f", row);
        // Printed and fitted, not written: --c2f-csv holds the cold rows the plot draws.
        record("warm", triangles, "c2f", row, nullptr);
      }
      if (start_errors.size() > 1) {
        std::vector<double> means;
        ErrorMm e;
        for (const ErrorMm& s : start_errors) means.push_back(s.mean), e.max = std::max(e.max, s.max);
        e.mean = median(means);
        print_start_row(triangles, e);
      }
    }
  }

  // Cost growth over the sizes, per start and preset (converged rows and budget stops).
  std::vector<std::string> with_c2f = presets;
  with_c2f.push_back("c2f");
  bool first = true;
  for (const char* start : {"cold", "warm"})
    for (const std::string& preset : with_c2f) {
      std::vector<double> n, seconds, iterations, per_iteration;
      for (const Row& r : rows)
        if (r.start == start && r.preset == preset)
          n.push_back(r.triangles), seconds.push_back(r.seconds), iterations.push_back(r.iterations),
              per_iteration.push_back(r.seconds / r.iterations);
      if (n.size() < 2 || *std::min_element(n.begin(), n.end()) == *std::max_element(n.begin(), n.end())) continue;
      if (first) std::printf("cost growth, least squares in log-log over the sizes (time ~ n^p)\n"), first = false;
      std::printf("  %-4s %-9s %zu sizes: time n^%.2f, Newton iterations n^%.2f, time per iteration n^%.2f\n", start,
                  preset.c_str(), n.size(), growth_exponent(n, seconds), growth_exponent(n, iterations),
                  growth_exponent(n, per_iteration));
    }
  try {
    for (const CsvFile* f : {&csv, &warm_csv, &trajectory, &c2f_csv}) f->write();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drape_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
