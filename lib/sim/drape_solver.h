// Drapes a cloth model: backward Euler written as minimisation of the incremental potential,
// solved by Newton with exact element Hessians and Levenberg-Marquardt damping (where the exact
// Hessian is indefinite, projected membrane elements first: membrane_fallback; body contact's
// Hessian exact only near equilibrium: exact_contact_residual), CHOLMOD (one
// symbolic analysis; the system bisected and its halves factorised on two cores,
// BisectedCholesky) and a backtracking line search that never lets the energy rise.
//
// Static mode drives the drape to equilibrium with damped steps: each step minimises
// E(x) + damping |x - x_n|^2_D / 2, D the step metric (proximal_metric: the pattern's Laplacian
// plus a little mass by default, the mass matrix alone for a quasi-static backward-Euler step
// with damping = 1/h^2), and the damping falls while steps succeed, so the iteration turns into
// Newton's method on E (Levenberg-Marquardt damping by D).
// It stops when the relative force residual |grad E|_2 / |m g|_2 over the free degrees of
// freedom falls to the tolerance. Dynamic mode integrates with momentum and stops when the
// drape is at rest (residual and kinetic energy below tolerance).
//
// Presets: Accurate refactorises every Newton iteration with exact element Hessians and stops
// at the tolerance; Fast is the same iteration stopped at fast_tolerance_factor times the
// tolerance, and on a re-drape (redrape_settings) after fast_redrape_budget Newton iterations
// at the latest, not at an equilibrium. Measured and rejected for Fast (skirt, 5K triangles,
// bench/): Gauss-Newton element Hessians (3000 iterations without converging, vs 377 for
// exact), and reusing one factorisation for up to 10 iterations (stale damping shortens the
// steps: 928 iterations instead of 37 on a 2K box cover). A looser stop is no cheaper either:
// the residual stays high while folds form and then collapses quadratically (5K skirt:
// tolerance 1e-2 saves 40 % of the iterations at 3.6 mm mean error; 3e-3 saves 1 %).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sim/cloth_energy.h"
#include "sim/bisected_cholesky.h"

namespace foldsketch {

// The metric of static mode's quasi-static steps (DrapeSettings::proximal_metric).
enum class ProximalMetric {
  Mass,      // |y - x_n|^2_M: a backward-Euler step from rest
  Laplacian  // |y - x_n|^2 in m_mean L + laplacian_mass_share M (L: the pattern's Laplacian)
};

struct DrapeSettings {
  SimulationMode mode = SimulationMode::Static;
  SolverPreset preset = SolverPreset::Accurate;
  double time_step = 0.01;          // [s]: dynamic step, or the first quasi-static step
  int max_steps = SimulatorSettings{}.max_steps;  // Newton iterations (static) or time steps (dynamic)
  // Dynamic mode: drag force -drag * M v [1/s] (air and internal friction), so a drape comes
  // to rest: a cloth pendulum under backward Euler alone keeps swinging for tens of seconds at
  // millisecond steps. 1/s halves a swing in about 0.7 s; our choice.
  double drag = 1.0;
  double tolerance = 1e-6;          // relative force residual at convergence
  // Largest move of any vertex in one Newton iteration [m]: a penalty force cannot stop a
  // vertex that jumps through a body part in one step; 1 cm is under a limb's half width.
  double max_displacement = 0.01;
  // Quasi-static step control: the damping (1/h^2) is divided by damping_decrease after a full
  // Newton step and multiplied by damping_increase after a step the line search had to cut.
  // Measured on the 5K skirt, (decrease, increase) = (4, 2): 377 iterations; (3, 3): 267;
  // (2, 2): 409; (3, 4): 395; (2, 1.5): 471; (4, 3): 520; (4, 4): 556; (10, 10): 604;
  // (10, 2): 627. The spread is the path-dependence of fold formation, not a trend.
  double damping_decrease = 4.0;
  double damping_increase = 2.0;
  // Static mode: what the damping measures a step by. Mass damps every motion alike, and must
  // exceed the most negative curvature of the exact Hessian: where the cloth is compressed
  // (stress -s), the membrane's geometric stiffness is about -s k^2 A for a wrinkle of
  // wavenumber k, largest at the mesh scale, so a mass damping that makes the Hessian positive
  // definite there slows the fold-scale motion as much (the 20K skirt's 2 % re-drape kept it
  // at 1e6-2.5e7 s^-2 for its first 27 Newton iterations). The Laplacian damps a mode by k^2,
  // as that negative curvature grows, so one damping covers every wavelength and leaves the
  // long-wavelength motion (folds sliding, the garment settling) nearly free: the same
  // re-drape's relative residual fell from 109 to 1 in 9 iterations instead of 27. A little
  // mass (laplacian_mass_share) keeps the metric positive definite for a garment with
  // neither pins nor contact. Dynamic mode always uses the mass: it is the physics.
  // Measured (bench/drape_bench.txt, the size sweep, 9 skirts of 4.8K-23K triangles): Newton
  // iterations summed, warm (2 % re-drape) 1150 with the mass, 992 / 955 / 680 (7 sizes) with
  // mass shares 0.1 / 1 / 0.01; cold 4653 against 3930 / 5432 / 3759 (7 sizes, against 3334):
  // warm re-drapes are shorter at every share, cold drapes move within their path noise, best
  // at 0.1. Pinned sheets squeezed to 0.95 / 0.9 / 0.6 of their width, exact Hessian without
  // the membrane fallback: the mass metric did not converge in 1000 iterations, the Laplacian
  // took 18 / 33 / 132 (share 0.01), 29 / 52 / 333 (0.1), 169 / - / - (1). Share 0.1: our
  // choice from these.
  ProximalMetric proximal_metric = ProximalMetric::Laplacian;
  double laplacian_mass_share = 0.1;
  // Fast preset: residual at which it stops, as a multiple of `tolerance` (measured: see bench/).
  double fast_tolerance_factor = 100.0;
  // Static mode: Newton iterations after which the solve stops and returns the drape as it is,
  // DrapeStats::stopped_at_budget (0: no budget). Not an equilibrium: a truncation whose error
  // is measured, not bounded (no local model bounds how far folds still slide,
  // bench/drape_bench.txt). What the Fast preset does on re-drapes (redrape_settings).
  int newton_budget = 0;
  // The Fast preset's budget on a re-drape. Measured on the skirt's re-drapes from the stored
  // starts (bench/drape_bench.txt, 2026-12-06: 5K-20K, patterns 2, 5 and 10 % wider, 3 starts
  // each), after 20 Newton iterations 0.3-0.8 of the predicted start's distance to the
  // equilibrium is left, median 0.5 (20K: 1.1-1.8 -> 0.74-0.96 mm mean at 2 %, 3.0-4.0 ->
  // 1.29-1.88 mm at 5 %, 6.6-7.9 -> 3.09-3.29 mm at 10 %; 2.0-2.5 s), and 30 iterations take a
  // further fifth off. A cold drape (from a placement) moves tens of millimetres while its
  // folds form, so it has no budget: there Fast stops on its residual alone. 20: our choice,
  // the 3 s of the fast target at 20K triangles.
  int fast_redrape_budget = 20;
  // Element Hessians. Exact: near a stable equilibrium the assembled
  // Hessian is positive definite even where elements are not (compressed triangles, folded
  // hinges), and the damping grows only when CHOLMOD finds it is not. Projecting each element
  // instead adds stiffness to the soft fold modes, and the iteration then creeps: on the
  // 10K-triangle skirt it stalled at a residual of 2.5e-4 where the exact Hessian converged
  // quadratically.
  HessianKind membrane_hessian = HessianKind::Exact;
  HessianKind bending_hessian = HessianKind::Exact;
  // When the exact Hessian plus the damping is not positive definite, first try the same
  // damping with the membrane elements projected (bending stays exact), for that iteration and
  // the next membrane_fallback_iterations; more damping only when that fails too. It acts only
  // on a start that is far from the rest shape: some triangle squeezed below
  // membrane_fallback_stretch of its pattern size in some direction. Squeezed
  // triangles make the exact membrane Hessian indefinite, and more damping then shortens the
  // steps of every vertex: the Berkeley Garment Library skirt, hanging from its placement with
  // triangles at 0.58-1.45 times their pattern size, kept the damping at 1e4-5e5 s^-2 and took
  // 2817 iterations (66 s); with the fallback 264 (7 s). Where folds form from a start close
  // to the rest shape (the sample skirts), the buckling directions the exact Hessian has matter
  // more: with the fallback always on, 9 sizes from 5K to 23K were neutral within the path
  // noise, but the 54K skirt took 22 minutes instead of 6 (bench/drape_bench.txt). Projecting
  // every membrane element all the time took 1803 iterations on the 10K skirt (365 exact).
  // Iterations, 5: 264 on the BGL skirt with 304 factorisations; re-trying the exact Hessian
  // at every iteration, 264 with 506. Not solved by this rule, with the mass metric: a start
  // squeezed by less, with the squeezed edge pinned (a sheet at 0.95 of its width), crawls with
  // the exact Hessian (residual 2e-5 after 1000 iterations); the Laplacian metric converges in
  // 29 (proximal_metric). And
  // the projection removes exactly the curvature that points out of a flat, squeezed sheet: a
  // perfectly flat sheet at 0.98, forced to fall back (stretch 0.99), converges in 7 iterations
  // to the flat compressed state, an unstable equilibrium; the stability check at convergence
  // (stability_check) finds the saddle and the solve leaves it: 47 iterations in all, buckled
  // 6.4 mm out of the plane, lower energy. The flat sheet without the fallback ends at that
  // saddle too (no force leaves the plane), so the check is what guards both.
  bool membrane_fallback = true;
  // The sample skirts start at 1 (sewn placement) or 0.98 (re-drape with 2 % ease); the BGL
  // skirt's placement at 0.58 and the squeezed sheet of the DrapeSolver test at 0.6. Our
  // choice between them.
  double membrane_fallback_stretch = 0.9;
  int membrane_fallback_iterations = 5;
  // Newton iterations on projected membranes after which the fallback stops for the rest of the
  // solve: projected Newton converges only linearly, and where the exact Hessian keeps being
  // refused at the floor damping the fallback can hold it for good. The Berkeley Garment
  // Library garments hanging from their top band (bench/bgl_hang.sh, 21 isotropic meshes):
  // in thin cotton they took up to 582 projected iterations and converged (5260 Newton
  // iterations for the 21, against 7232 without the fallback); in silk blouse-short and shirt
  // were still at residual 0.06-0.09 after 3000 iterations, all but 2 of them projected, while
  // without the fallback they converged in 628 and 882, and with this budget in 1136 and 1518.
  // Our choice between the cotton runs' most and the silk runs' stall.
  int membrane_fallback_budget = 1000;
  // Body contact's Hessian is exact (with the curvature of the distance to the body, negative
  // sideways at the body's convex edges and corners) once the relative force residual is at
  // or below this, and without that curvature above it (ClothEnergy::evaluate). Exact from
  // the start, the folds form on longer paths: cold 5K and 10K skirts took 513 and 747 Newton
  // iterations against 357 and 361. Without it at the end, Newton converges only linearly,
  // by a factor 0.85 per iteration (the 20K re-drape took 26 iterations from residual 1e-4 to
  // 1e-6); with it, 5 iterations to 3e-10 (156 iterations in all against 135).
  // 100 times the default tolerance: below the residuals of fold formation (1e-3 and above
  // while the folds move), our choice.
  double exact_contact_residual = 1e-4;
  // Static mode: the line search follows x + a dx + a^2 c, c the step's second-order part that
  // keeps regions turning as a whole from stretching (StepCurvature; one solve with the
  // pattern's Laplacian per Newton iteration). Measured on the 2 % re-drapes from the 12 stored
  // starts (5K-54K, bench/drape_bench.txt): Newton iterations 1584 -> 1299, factorisations
  // 1978 -> 1676, fewer from 10 of 12 starts, 54K 155 / 249 / 251 -> 113 / 162 / 179; ending at
  // the same drapes (within 0.05 um mean at 5K and 10K; 0.05 and 0.23 mm mean at two 20K
  // starts). Not with self-contact: on the pleat pressed flat (HardCases) curved steps took 929
  // Newton iterations against 206 (768 with the straight step's layer bound; traced, the cause
  // not found: bench/drape_bench.txt), and the step bound there holds for straight steps.
  bool curved_steps = true;
  // Static mode with the Laplacian metric: each triangle's term of the metric's Laplacian is
  // weighted by stress_metric_floor + c / stress_metric_reference, c its compressive stress at
  // the step's start (ClothEnergy::compressive_stress; 0 where it is not compressed).
  // Why: the damping must outweigh the exact Hessian's most negative curvature, measured in the
  // metric, and that curvature is the membrane's geometric stiffness in compressed triangles
  // (after the patterns widen, below the pinned waist; where folds form), A B^T S B >= -c A B^T B:
  // the triangle's Laplacian term times c (test ClothEnergy.CompressiveStressBoundsTheGeometric-
  // Stiffness). With the plain Laplacian the damping that holds it there damps the whole
  // garment, and the folds sliding in cloth under tension, whose curvature is far lower, moved
  // a few percent of their way per Newton iteration (bench/drape_bench.txt). Weighted by c, one
  // damping holds the compressed triangles wherever they are, and cloth in tension is damped
  // only by the floor. Measured on the skirt (bench/drape_bench.txt, one run per start, Newton
  // iterations summed, plain -> weighted): 2 % re-drapes from the 9 stored starts at 5K-20K,
  // isotropic mesh 597 -> 445, grid 725 -> 610; 5 % re-drapes, isotropic 1128 -> 718; cold
  // drapes at five sizes from 5K to 20K, isotropic 2147 -> 1629, grid 1706 -> 1095. Floor and
  // reference (0.1, 0.01 N/m) and (0.03, 0.01 N/m) were within a few percent of this choice;
  // (0.1, 1 N/m), nearer the plain metric, gained half as much. Not with self-contact: the
  // 600-triangle flag sample with self-contact everywhere fell in steps of 40-80 mm, nearly
  // undamped, and jammed (damping at its bound after 470 Newton iterations, residual 1.6,
  // strain 14 %), where the plain metric converged in 643. 0 reference: the plain metric.
  double stress_metric_floor = 0.03;
  double stress_metric_reference = 0.03;  // [N/m]
  // Static mode: at convergence, check that the drape is a stable equilibrium (lib/sim/
  // stability.h: the exact Hessian plus kNeutralCurvature times the mass positive definite),
  // and if it is a saddle, leave it along the direction of most negative curvature and go on
  // solving, at most max_saddle_escapes times. A symmetric start can converge to a saddle: a
  // flat sheet squeezed in its plane stays flat, since no force leaves the plane (test
  // DrapeSolver.LeavesASaddleAlongItsNegativeCurvature). Costs one factorisation at the end
  // when the drape is stable. 10: our choice; the sheet needs one.
  bool stability_check = true;
  int max_saddle_escapes = 10;
  // The Newton systems' factorisation (BisectedCholesky): Single factorises in single
  // precision (lib/sim/supernodal_single.h) and refines each solve once in double; a solve
  // whose refined residual still misses (the system too ill-conditioned, as with a stiff
  // membrane under a light load) is rescued by up to rescue_iterations conjugate-gradient
  // iterations preconditioned by the factor (BisectedSettings::rescue_iterations); one whose
  // rescue finds negative curvature counts as a failed factorisation (more damping); one that
  // the rescue leaves inaccurate switches the rest of the solve to double precision
  // (DrapeStats::double_precision_fallback). The stability check's verdict is always reached in
  // double precision. Measured (bench/drape_bench.txt, 2026-12-07): 20K-triangle skirt, 2 %
  // re-drapes from the 3 stored starts 6.77 -> 4.78 s median, the same Newton iterations
  // (62 / 74 / 56 -> 61 / 78 / 56); cold 34.5 -> 26.0 s; a factorisation 69 -> 38 ms.
  FactorPrecision factor_precision = FactorPrecision::Single;
  // 0 turns the rescue off (for measurements). Measured (bench/drape_bench.txt, 2026-12-07,
  // session 46): the 20K skirt's cold drape no longer falls back to double precision at its
  // 196th solve, where the single factor had passed an indefinite matrix.
  int rescue_iterations = BisectedSettings{}.rescue_iterations;
};

DrapeSettings drape_settings(const SimulatorSettings& scene);

// The settings of a re-drape: a static solve from near an equilibrium under other patterns
// (PatternChangeStep::near_equilibrium; or its predicted response, lib/sim/pattern_change.h),
// which a drape stopped at this budget is too. With the Fast preset, the solve stops after
// fast_redrape_budget Newton iterations at the latest (newton_budget; a smaller one already
// set stays); the Accurate preset is unchanged.
DrapeSettings redrape_settings(DrapeSettings settings);

// The line searches' Armijo sufficient-decrease constant and the shortest step they try.
constexpr double kLineSearchArmijo = 1e-4, kLineSearchMinStep = 1.0 / 1024;

// x + alpha dx + alpha^2 bend over the free vertices (dx, bend: 3 per free vertex; no bend
// when it is empty).
MatrixX3d moved_along(const MatrixX3d& x, const VectorXd& dx, const VectorXd& bend, const std::vector<int>& free_vertices,
                double alpha);

// The longest fraction of the straight step x + alpha dx (dx: 3 per free vertex) along which
// no cloth layer passes through another: each cloth-cloth gap closes by at most 90 % of itself
// (self_contact_step_bound). 1 without self-contact.
double longest_layer_safe_step(const ClothModel& model, const MatrixX3d& x, const VectorXd& dx,
                               const std::vector<int>& free_vertices);

// What the relative force residual is relative to: the 2-norm of the free cloth's weight; with
// no gravity, a membrane force (the stiffer stretch stiffness times the square root of the
// cloth's area).
double residual_scale(const ClothModel& model, const ClothEnergy& energy);

// The relative force residual at which the solver stops: the tolerance, times
// fast_tolerance_factor for the Fast preset.
double stopping_tolerance(const DrapeSettings& settings);

// Whether the drape a static solve converged to is a stable equilibrium (DrapeSettings::
// stability_check).
enum class Stability { NotChecked, Stable, Unstable };
const char* to_string(Stability stability);

struct DrapeStats {
  bool converged = false;
  Stability stability = Stability::NotChecked;
  int saddle_escapes = 0;           // saddles left along their negative curvature on the way
  double lowest_curvature = 0;      // Unstable: the most negative eigenvalue of M^-1 H [1/s^2]
  bool double_precision_fallback = false;  // single-precision factors gave no usable step; double from then on
  int rescue_iterations = 0;        // conjugate-gradient iterations rescuing single-precision solves
  int indefinite_solves = 0;        // single-precision factors of matrices the rescue found indefinite
  std::string message;              // why it stopped, in words
  bool out_of_steps = false;        // stopped by max_steps, not converged (the energy was still falling)
  bool stopped_at_budget = false;   // stopped by DrapeSettings::newton_budget, as asked (not converged)
  int steps = 0;                    // accepted steps
  int newton_iterations = 0;
  int factorizations = 0;
  int projected_iterations = 0;     // Newton iterations on the Hessian with projected membrane elements
  double residual = 0;              // relative force residual (2-norms, free DOFs)
  EnergyTerms energy;               // [J]
  double kinetic_energy = 0;        // [J]
  double max_strain = 0;            // largest principal stretch minus 1
  double max_penetration = 0;       // deepest vertex inside the body surface [m]
  // Closest approach of two cloth elements that self-contact keeps apart (vertex-triangle or
  // edge-edge) [m]; the contact thickness when none is closer, NaN without self-contact.
  double min_self_distance = std::numeric_limits<double>::quiet_NaN();
  double step_fraction = 0;         // line-search fraction of the last Newton step
  double step_length = 0;           // largest vertex move of the last step [m]
  double damping = 0;               // 1/h^2 of the last quasi-static step [1/s^2]
  // seconds_curvature: the curved steps' Laplacian solves (DrapeSettings::curved_steps).
  double seconds_assembly = 0, seconds_factorization = 0, seconds_solve = 0, seconds_curvature = 0, seconds_line_search = 0,
         seconds_total = 0;
};

struct DrapeResult {
  MatrixX3d V;                      // the drape; always finite (the last finite state on failure)
  DrapeStats stats;
};

// Called after every accepted step with the stats so far and the drape, and once more at the
// end with the final stats and the result's drape.
using DrapeProgress = std::function<void(const DrapeStats&, const MatrixX3d&)>;

// factorisation: the Newton systems' factorisation to use instead of the solve's own, e.g. the
// one predict_pattern_change analysed for the same garment: its analysis is reused when it is
// of this model's Hessian pattern (about 0.3 s at 20K triangles), and its precision is set
// from settings.factor_precision.
DrapeResult solve_drape(const ClothModel& model, const MatrixX3d& initial, const DrapeSettings& settings,
                        const DrapeProgress& progress = {}, BisectedCholesky* factorisation = nullptr);

// Largest principal stretch minus 1 over the model's triangles.
double max_strain(const ClothModel& model, const MatrixX3d& x);
// Smallest principal stretch over the model's triangles (1 at the rest shape).
double min_stretch(const ClothModel& model, const MatrixX3d& x);
// Deepest vertex inside the body surface [m] (0 when none, or no body).
double max_penetration(const ClothModel& model, const MatrixX3d& x);
// Closest approach of two cloth elements under self-contact [m] (see DrapeStats).
double min_self_distance(const ClothModel& model, const MatrixX3d& x);

} // namespace foldsketch
