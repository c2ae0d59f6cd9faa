#include "sim/drape_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Eigenvalues>

#include "core/error.h"
#include "sim/self_contact.h"
#include "sim/bisected_cholesky.h"
#include "sim/stability.h"
#include "sim/step_curvature.h"

namespace foldsketch {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Damping bounds of the quasi-static steps, as 1/h^2 [1/s^2]: below 1 s^-2 the mass term is
// negligible next to any fabric stiffness (a vertex mass of 1e-5 kg against 1e2 N/m), above
// 1e12 (h = 1 us) no step is possible and the solve has failed.
constexpr double kMinDamping = 1e-6, kMaxDamping = 1e12;
// Energy changes below this fraction of the summed magnitudes of the energy terms are
// roundoff: near equilibrium the Armijo test cannot see them, and a full step that lowers the
// force residual is taken instead.
constexpr double kRoundoff = 1e-12;
// Dynamic mode: a time step whose Newton iterations stopped early is still taken when the
// incremental potential's force residual is below this fraction of the weight; its error is
// then far below one step's inertial forces, and the drag and later steps absorb it. Otherwise
// the step is halved.
constexpr double kStepAcceptance = 1e-3;
// Leaving a saddle (DrapeSettings::stability_check): the first try's largest vertex move [m],
// a tenth of the 1 cm step bound (DrapeSettings::max_displacement), and the damping the solve
// resumes with, at least: its descent then follows the gradient, which points off the saddle,
// where a barely damped step along the unstable mode is as long as the damping is near its
// negative curvature, and the line search would cut it many times. Our choices.
constexpr double kSaddleEscape = 1e-3;
constexpr double kSaddleDamping = 1.0;
// Self-contact: one step may close at most this fraction of any cloth-cloth gap, so no layer
// passes through another between two states (our choice: nearer 1, contact is approached in
// fewer, riskier steps).
constexpr double kSelfContactClosing = 0.9;

} // namespace

double longest_layer_safe_step(const ClothModel& model, const MatrixX3d& x, const VectorXd& dx,
                               const std::vector<int>& free_vertices) {
  if (!model.self_contact) return 1.0;
  MatrixX3d step = MatrixX3d::Zero(x.rows(), 3);
  for (size_t a = 0; a < free_vertices.size(); ++a) step.row(free_vertices[a]) = dx.segment<3>(3 * static_cast<Eigen::Index>(a)).transpose();
  return self_contact_step_bound(*model.self_contact, x, step, 1.0 - kSelfContactClosing);
}

// Largest move of any vertex in dx (3 per free vertex) [m].
double largest_vertex_move(const VectorXd& dx) {
  double largest = 0.0;
  for (Eigen::Index a = 0; 3 * a < dx.size(); ++a) largest = std::max(largest, dx.segment<3>(3 * a).norm());
  return largest;
}

MatrixX3d moved_along(const MatrixX3d& x, const VectorXd& dx, const VectorXd& bend, const std::vector<int>& free_vertices,
                double alpha) {
  MatrixX3d y = x;
  for (size_t a = 0; a < free_vertices.size(); ++a) {
    const long i = 3 * static_cast<long>(a);
    y.row(free_vertices[a]) += alpha * dx.segment<3>(i).transpose();
    if (bend.size() > 0) y.row(free_vertices[a]) += alpha * alpha * bend.segment<3>(i).transpose();
  }
  return y;
}

const char* to_string(Stability stability) {
  switch (stability) {
    case Stability::Stable: return "stable";
    case Stability::Unstable: return "unstable";
    default: return "not checked";
  }
}

double residual_scale(const ClothModel& model, const ClothEnergy& energy) {
  const double weight = energy.gravity_force().norm();
  if (weight > 0.0) return weight;
  return std::max(model.material.stretch_warp, model.material.stretch_weft) * std::sqrt(model.contact_area.sum());
}

DrapeSettings drape_settings(const SimulatorSettings& scene) {
  DrapeSettings s;
  s.mode = scene.mode;
  s.preset = scene.preset;
  s.time_step = scene.time_step;
  s.max_steps = scene.max_steps;
  s.tolerance = scene.tolerance;
  return s;
}

DrapeSettings redrape_settings(DrapeSettings settings) {
  if (settings.preset == SolverPreset::Fast && settings.fast_redrape_budget > 0 &&
      (settings.newton_budget <= 0 || settings.fast_redrape_budget < settings.newton_budget))
    settings.newton_budget = settings.fast_redrape_budget;
  return settings;
}

namespace {
double principal_stretch(const ClothModel& model, const MatrixX3d& x, size_t t, int which) {
  const auto& v = model.triangles[t];
  const Eigen::Vector3d e = green_strain(x.row(v[0]), x.row(v[1]), x.row(v[2]), model.rest[t]);
  const Eigen::Matrix2d E = (Eigen::Matrix2d() << e(0), e(2), e(2), e(1)).finished();
  const double value = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(E, Eigen::EigenvaluesOnly).eigenvalues()(which);
  return std::sqrt(std::max(0.0, 1.0 + 2.0 * value));
}
} // namespace

double max_strain(const ClothModel& model, const MatrixX3d& x) {
  double worst = 0.0;
  for (size_t t = 0; t < model.triangles.size(); ++t) worst = std::max(worst, principal_stretch(model, x, t, 1) - 1.0);
  return worst;
}

double min_stretch(const ClothModel& model, const MatrixX3d& x) {
  double least = 1.0;
  for (size_t t = 0; t < model.triangles.size(); ++t) least = std::min(least, principal_stretch(model, x, t, 0));
  return least;
}

double max_penetration(const ClothModel& model, const MatrixX3d& x) {
  if (!model.body) return 0.0;
  double deepest = 0.0;
  for (int v = 0; v < x.rows(); ++v) deepest = std::max(deepest, -model.body->at(x.row(v)).distance);
  return deepest;
}

double min_self_distance(const ClothModel& model, const MatrixX3d& x) {
  if (!model.self_contact) return std::numeric_limits<double>::quiet_NaN();
  const SelfContactModel& sc = *model.self_contact;
  double closest = sc.thickness;
  for (const auto& [v, t] : self_contact_pairs(sc, x, sc.thickness)) {
    const auto& tri = sc.triangles[static_cast<size_t>(t)];
    closest = std::min(closest, point_triangle_distance(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2])));
  }
  for (const auto& [e, f] : self_contact_edge_pairs(sc, x, sc.thickness)) {
    const auto &a = sc.edges[static_cast<size_t>(e)], &b = sc.edges[static_cast<size_t>(f)];
    closest = std::min(closest, segment_segment_distance(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1])));
  }
  return closest;
}

double stopping_tolerance(const DrapeSettings& settings) {
  return settings.tolerance * (settings.preset == SolverPreset::Fast ? settings.fast_tolerance_factor : 1.0);
}

DrapeResult solve_drape(const ClothModel& model, const MatrixX3d& initial, const DrapeSettings& settings,
                        const DrapeProgress& progress, BisectedCholesky* factorisation) {
  const auto start = Clock::now();
  if (initial.rows() != model.vertex_count) throw ArgumentError("solve_drape: initial drape has the wrong number of vertices");
  if (!initial.allFinite()) throw ArgumentError("solve_drape: the initial drape has NaN or Inf coordinates");
  DrapeResult result;
  DrapeStats& stats = result.stats;
  MatrixX3d x = initial;
  for (const Pin& p : model.pins) x.row(p.vertex) = p.position.transpose();

  ClothEnergy energy(model);
  const int n = energy.free_count();
  const VectorXd& mass = energy.free_mass();
  const HessianKind membrane_kind = settings.membrane_hessian;
  const HessianKind bending_kind = settings.bending_hessian;
  const double tolerance = stopping_tolerance(settings);
  const bool dynamic = settings.mode == SimulationMode::Dynamic;

  // Residual scale: the weight of the free cloth; without gravity, a membrane force (stretch
  // stiffness times the square root of the cloth's area).
  const double scale = residual_scale(model, energy);
  const double work_scale = scale * std::max(1e-3, (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm());

  BisectedSettings factor_settings;
  factor_settings.precision = settings.factor_precision;
  BisectedCholesky own_factorisation(factor_settings);
  BisectedCholesky& cholesky = factorisation ? *factorisation : own_factorisation;
  cholesky.set_precision(settings.factor_precision);
  cholesky.set_rescue_iterations(settings.rescue_iterations);
  // A handed-in factorisation's counts and times so far are not this solve's.
  const int factorizations_before = cholesky.factorizations();
  const int rescue_before = cholesky.rescue_iterations();
  const double factor_seconds_before = cholesky.factorize_seconds() + cholesky.analyze_seconds();
  const double solve_seconds_before = cholesky.solve_seconds();
  bool pattern_checked = false;  // a handed-in analysis is reused only for the same pattern
  SparseMatrix A = energy.pattern();
  // Curved steps (DrapeSettings::curved_steps): static mode only, and not with self-contact,
  // whose step bound holds for the straight step.
  std::optional<StepCurvature> curvature;
  if (settings.curved_steps && !dynamic && !model.self_contact && n > 0) curvature.emplace(model, energy);
  VectorXd velocity = VectorXd::Zero(3 * n);
  double h = settings.time_step;
  double damping = 1.0 / (h * h);
  bool factor_current = false;

  // The incremental potential Phi(y) = E(y) + damping |y - x_hat|^2_D / 2, x_hat = x_n + h v_n
  // (v_n = 0 in static mode), damping = 1/h^2, D the mass matrix M, or in static mode with the
  // Laplacian metric (DrapeSettings::proximal_metric) m_mean L + laplacian_mass_share M.
  MatrixX3d x_step = x;
  const bool laplacian_metric = !dynamic && settings.proximal_metric == ProximalMetric::Laplacian;
  const double metric_mass = laplacian_metric ? settings.laplacian_mass_share : 1.0;
  const double metric_laplacian = laplacian_metric && n > 0 ? mass.sum() / (3.0 * n) : 0.0;
  // Not with self-contact (DrapeSettings::stress_metric_reference).
  const bool stress_metric = laplacian_metric && settings.stress_metric_reference > 0.0 && !model.self_contact;
  VectorXd metric_weights;  // per triangle, set at each step's start (DrapeSettings::stress_metric_reference)
  const VectorXd* const weights = stress_metric ? &metric_weights : nullptr;
  // Dynamic mode adds the drag potential drag/(2h) |y - x_n|^2_M (force -drag M v_{n+1}).
  const auto inertia = [&](const MatrixX3d& y, VectorXd* grad) {
    double value = 0.0;
    const double drag = dynamic ? settings.drag / h : 0.0;
    if (laplacian_metric) {
      VectorXd d(3 * n);
      for (int a = 0; a < n; ++a) {
        const int v = energy.free_vertices()[a];
        d.segment<3>(3 * a) = (y.row(v) - x_step.row(v)).transpose();
      }
      const VectorXd force = damping * (metric_laplacian * energy.laplacian_times(d, weights) + metric_mass * mass.cwiseProduct(d));
      if (grad) *grad += force;
      return 0.5 * d.dot(force);
    }
    for (int a = 0; a < n; ++a) {
      const int v = energy.free_vertices()[a];
      const Eigen::Vector3d moved_by = (y.row(v) - x_step.row(v)).transpose();
      Eigen::Vector3d d = moved_by;
      if (dynamic) d -= h * velocity.segment<3>(3 * a);
      value += 0.5 * mass(3 * a) * (damping * d.squaredNorm() + drag * moved_by.squaredNorm());
      if (grad) grad->segment<3>(3 * a) += mass(3 * a) * (damping * d + drag * moved_by);
    }
    return value;
  };
  // The membrane Hessian of the current iteration: membrane_kind, or projected while the
  // fallback (DrapeSettings::membrane_fallback) holds; fallback_left more iterations to go.
  HessianKind membrane_now = membrane_kind;
  int fallback_left = 0;
  const bool fallback_allowed = settings.membrane_fallback && membrane_kind == HessianKind::Exact &&
                                min_stretch(model, x) < settings.membrane_fallback_stretch;
  // The contact Hessian of the current iteration (DrapeSettings::exact_contact_residual).
  HessianKind contact_now = HessianKind::GaussNewton;
  // Energy (and derivatives) of E alone; timing kept per phase.
  const auto evaluate = [&](const MatrixX3d& y, VectorXd* grad, SparseMatrix* hess) {
    const auto t0 = Clock::now();
    const EnergyTerms e = energy.evaluate(y, grad, hess, membrane_now, bending_kind, contact_now);
    stats.seconds_assembly += since(t0);
    return e;
  };
  // E's gradient and Hessian at y, with the Hessian pattern grown for self-contact first (and
  // the factorisation's analysis redone when it grew).
  const auto assemble = [&](const MatrixX3d& y, VectorXd* grad) {
    const bool grew = energy.prepare(y);
    if (grew || (!pattern_checked && n > 0 && !cholesky.analysed_for(energy.pattern()))) cholesky.analyze(energy.pattern());
    pattern_checked = true;
    factor_current = false;
    return evaluate(y, grad, &A);
  };
  const auto phi_only = [&](const MatrixX3d& y) {
    const double value = evaluate(y, nullptr, nullptr).total() + inertia(y, nullptr);
    return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
  };
  const auto report = [&](const MatrixX3d& drape) {
    stats.factorizations = cholesky.factorizations() - factorizations_before;
    stats.rescue_iterations = cholesky.rescue_iterations() - rescue_before;
    stats.seconds_factorization = cholesky.factorize_seconds() + cholesky.analyze_seconds() - factor_seconds_before;
    stats.seconds_solve = cholesky.solve_seconds() - solve_seconds_before;
    stats.seconds_total = since(start);
    if (progress) progress(stats, drape);
  };

  // One damped Newton iteration on Phi from x, given Phi's gradient g there and E's Hessian
  // in A (just assembled). Returns false when no step lowered Phi.
  double applied_damping = 0.0;  // damping already added to A since its assembly
  // phi: Phi(x), known to the caller from the evaluation that gave g.
  // The damped Hessian in A is not positive definite: projected membrane elements at the same
  // damping first (while the fallback is allowed), else more damping on the same Hessian.
  // False when the damping has exceeded its bound.
  const auto not_definite = [&]() {
    factor_current = false;
    if (fallback_allowed && membrane_now == HessianKind::Exact && stats.projected_iterations < settings.membrane_fallback_budget) {
      membrane_now = HessianKind::Projected;
      fallback_left = settings.membrane_fallback_iterations;
      evaluate(x, nullptr, &A);
      applied_damping = 0.0;
      return true;
    }
    damping *= 10.0;
    return damping <= kMaxDamping;
  };
  const auto newton_iteration = [&](VectorXd& g, double phi) {
    applied_damping = 0.0;
    for (int attempt = 0; attempt < 60; ++attempt) {
      if (!factor_current) {
        const double mass_term = damping + (dynamic ? settings.drag / h : 0.0);
        energy.add_mass(A, metric_mass * (mass_term - applied_damping));
        if (laplacian_metric) energy.add_laplacian(A, metric_laplacian * (mass_term - applied_damping), weights);
        applied_damping = mass_term;
        factor_current = cholesky.factorize(A);
        if (!factor_current) {
          if (!not_definite()) return false;
          continue;
        }
      }
      ++stats.newton_iterations;
      if (membrane_now != membrane_kind) ++stats.projected_iterations;
      VectorXd dx = cholesky.solve(-g);
      if (cholesky.last_solve_indefinite()) {
        // The single-precision factorisation passed a matrix that is not positive definite
        // (its rescue found negative curvature): as a refused factorisation. Before this, such
        // a solve switched to double precision for the rest of the drape, whose factorisations
        // take twice as long (the 20K skirt's cold drape, from its 196th).
        ++stats.indefinite_solves;
        if (!not_definite()) return false;
        continue;
      }
      if (!cholesky.last_solve_trusted()) {
        // Too ill-conditioned for a single-precision factor: double precision from here on.
        cholesky.set_precision(FactorPrecision::Double);
        stats.double_precision_fallback = true;
        factor_current = false;
        continue;
      }
      double slope = g.dot(dx);
      if (!(slope < 0.0)) {  // no descent (roundoff in a nearly singular factor): refactorise
        factor_current = false;
        continue;
      }
      double largest = largest_vertex_move(dx);
      if (model.body && largest > settings.max_displacement) {
        dx *= settings.max_displacement / largest;
        slope *= settings.max_displacement / largest;
        largest = settings.max_displacement;
      }
      // The longest step that no cloth layer passes through another on (1 without self-contact).
      const double longest = longest_layer_safe_step(model, x, dx, energy.free_vertices());
      VectorXd bend;  // the path's second-order part: x + alpha dx + alpha^2 bend
      if (curvature) {
        const auto t1 = Clock::now();
        bend = (*curvature)(x, dx);
        stats.seconds_curvature += since(t1);
      }
      const auto t0 = Clock::now();
      const auto along = [&](double a) { return moved_along(x, dx, bend, energy.free_vertices(), a); };
      double alpha = longest;
      MatrixX3d trial = along(alpha);
      while (phi_only(trial) > phi + kLineSearchArmijo * alpha * slope && alpha >= kLineSearchMinStep) {
        alpha *= 0.5;
        trial = along(alpha);
      }
      if (alpha < kLineSearchMinStep) {  // in the roundoff regime, judge the full step by its forces
        const EnergyTerms& e = stats.energy;
        const double magnitude = std::abs(e.membrane) + std::abs(e.bending) + std::abs(e.gravity) + std::abs(e.stitches) +
                                 std::abs(e.contact) + std::abs(e.self_contact) + std::abs(phi);
        MatrixX3d full = along(longest);
        if (phi_only(full) <= phi + kRoundoff * magnitude) {
          VectorXd g_full;
          evaluate(full, &g_full, nullptr);
          inertia(full, &g_full);
          if (g_full.norm() < g.norm()) {
            alpha = longest;
            trial = std::move(full);
          }
        }
      }
      stats.seconds_line_search += since(t0);
      if (alpha < kLineSearchMinStep) {  // no decrease along this direction: more damping
        factor_current = false;
        damping *= 10.0;
        if (damping > kMaxDamping) return false;
        continue;
      }
      x = std::move(trial);
      stats.step_fraction = alpha;
      stats.step_length = alpha * largest;
      stats.damping = damping;
      if (!dynamic) {
        stats.kinetic_energy = 0.5 * damping * alpha * alpha * dx.dot(mass.cwiseProduct(dx));
        // Grow the quasi-static step after a full Newton step, shrink it after a cut one.
        damping = alpha == 1.0 ? std::max(kMinDamping, damping / settings.damping_decrease)
                               : std::min(kMaxDamping, damping * settings.damping_increase);
      }
      return true;
    }
    return false;
  };

  // Moves x off a saddle along mode (free DOFs): the largest vertex move starts at
  // kSaddleEscape and halves until one of the two directions lowers E below energy_at_x.
  const auto leave_saddle = [&](MatrixX3d& y, const VectorXd& mode, double energy_at_y) {
    const double largest = largest_vertex_move(mode);
    if (!(largest > 0.0)) return false;
    for (double move = kSaddleEscape; move >= kSaddleEscape / 1024; move *= 0.5) {
      for (double sign : {1.0, -1.0}) {
        MatrixX3d trial = moved_along(y, mode, VectorXd(), energy.free_vertices(), sign * move / largest);
        if (evaluate(trial, nullptr, nullptr).total() < energy_at_y) {
          y = std::move(trial);
          damping = std::max(damping, kSaddleDamping);
          return true;
        }
      }
    }
    return false;
  };

  for (int iteration = 0;; ++iteration) {
    // E's gradient and Hessian at the current drape; every iteration factorises afresh.
    VectorXd g;
    if (fallback_left > 0) --fallback_left;
    else membrane_now = membrane_kind;
    // The residual of the last iteration's drape picks the contact Hessian of this one.
    contact_now = iteration > 0 && stats.residual <= settings.exact_contact_residual ? HessianKind::Exact : HessianKind::GaussNewton;
    stats.energy = assemble(x, &g);
    stats.residual = n > 0 ? g.norm() / scale : 0.0;
    if (dynamic) stats.kinetic_energy = 0.5 * velocity.dot(mass.cwiseProduct(velocity));
    if (!std::isfinite(stats.residual)) {
      stats.message = "diverged: the forces became NaN or infinite";
      break;
    }
    const bool at_rest = !dynamic || stats.kinetic_energy <= settings.tolerance * work_scale;
    if (stats.residual <= tolerance && at_rest) {
      if (!dynamic && settings.stability_check && n > 0) {
        // Is it a minimum? The exact Hessian at x, every term exact (lib/sim/stability.h).
        const auto t0 = Clock::now();
        energy.evaluate(x, nullptr, &A, HessianKind::Exact, HessianKind::Exact, HessianKind::Exact);
        stats.seconds_assembly += since(t0);
        factor_current = false;
        const StabilityCheck check = check_stability(energy, A, cholesky);
        if (!check.stable && stats.saddle_escapes < settings.max_saddle_escapes && check.mode.size() > 0 &&
            leave_saddle(x, check.mode, stats.energy.total())) {
          ++stats.saddle_escapes;
          ++stats.steps;
          report(x);
          continue;
        }
        stats.stability = check.stable ? Stability::Stable : Stability::Unstable;
        if (!check.stable) stats.lowest_curvature = check.lowest_eigenvalue;
      }
      stats.converged = true;
      stats.message = "converged";
      if (stats.stability == Stability::Unstable) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "converged to an unstable equilibrium (a saddle: curvature %.3g s^-2 along its softest mode, "
                      "after %d escapes); a disturbed start may drape elsewhere",
                      stats.lowest_curvature, stats.saddle_escapes);
        stats.message = text;
      }
      break;
    }
    if (!dynamic && settings.newton_budget > 0 && stats.newton_iterations >= settings.newton_budget) {
      char text[200];
      std::snprintf(text, sizeof text, "stopped at its budget of %d Newton iterations with relative residual %.3g (not an equilibrium)",
                    settings.newton_budget, stats.residual);
      stats.message = text;
      stats.stopped_at_budget = true;
      break;
    }
    if (iteration >= settings.max_steps) {
      char text[200];
      std::snprintf(text, sizeof text, "stopped after %d %s with relative residual %.3g above %.3g", settings.max_steps,
                    dynamic ? "time steps" : "iterations", stats.residual, tolerance);
      stats.message = text;
      stats.out_of_steps = true;
      break;
    }

    x_step = x;
    if (stress_metric) {
      metric_weights = energy.compressive_stress(x) / settings.stress_metric_reference;
      metric_weights.array() += settings.stress_metric_floor;
    }
    if (!dynamic) {
      // At the start of a quasi-static step x = x_n, so Phi(x) = E(x), evaluated just above.
      if (!newton_iteration(g, stats.energy.total())) {
        stats.message = "stopped: no step lowers the energy (damping exceeded its bound); the drape is left where it was";
        break;
      }
    } else {
      // Newton on Phi until its gradient is small, else halve the step and retry.
      bool settled = false;
      VectorXd gphi = g;
      double phi = stats.energy.total() + inertia(x, &gphi);
      for (int k = 0; k < 30 && !settled; ++k) {
        if (k > 0) {
          gphi.setZero();
          phi = assemble(x, &gphi).total();
          phi += inertia(x, &gphi);
          if (gphi.norm() <= 0.1 * tolerance * scale) { settled = true; break; }
        }
        if (!newton_iteration(gphi, phi)) break;
      }
      if (!settled) {
        VectorXd gphi_end;
        evaluate(x, &gphi_end, nullptr);
        inertia(x, &gphi_end);
        settled = gphi_end.norm() <= kStepAcceptance * scale;
      }
      if (!settled) {
        x = x_step;
        h *= 0.5;
        damping = 1.0 / (h * h);
        factor_current = false;
        if (h < 1e-6) {
          stats.message = "stopped: the time step fell below 1 us without a converged step";
          break;
        }
        continue;
      }
      for (int a = 0; a < n; ++a) {
        const int v = energy.free_vertices()[a];
        velocity.segment<3>(3 * a) = (x.row(v) - x_step.row(v)).transpose() / h;
      }
      if (h < settings.time_step) h = std::min(settings.time_step, 2.0 * h);
      damping = 1.0 / (h * h);
    }
    ++stats.steps;
    report(x);
  }
  if (!x.allFinite()) {
    x = initial;
    stats.converged = false;
    stats.stopped_at_budget = false;
    stats.message = "diverged: NaN in the drape; returning the initial drape";
  }
  result.V = std::move(x);
  stats.max_strain = max_strain(model, result.V);
  stats.max_penetration = max_penetration(model, result.V);
  stats.min_self_distance = min_self_distance(model, result.V);
  report(result.V);
  return result;
}

} // namespace foldsketch
