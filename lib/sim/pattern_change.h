// A re-drape's first step: the first-order response of an equilibrium to a change of its
// patterns (the Euler predictor of continuation methods).
//
// x0 is an equilibrium of the cloth model `before` (old patterns); `after` is the same garment
// with new patterns. The equilibrium moves, to first order, by dx = -H^-1 g, H the Hessian of
// `before` at x0 (positive definite at a stable equilibrium) and g the forces of `after` at x0.
// Newton's method on `after` from x0 cannot take that step: after the change its Hessian at x0
// is indefinite where the change slackens the cloth (compressed triangles buckle), so the
// damping that makes it definite also shortens the steps of the folds, and the folds creep
// there (bench/drape_bench.txt). The old Hessian has no such compression and gives the
// response in one solve. Measured on the benchmark skirt, 20K triangles, patterns 5 % wider,
// stored start 1: the step takes the mean distance to the end from 3.8 to 2.2 mm, which damped
// Newton needs about 40 iterations for.
//
// The step is taken only where it is safe to: the start must be a stable equilibrium of
// `before` (forces under `before` at most max_force_ratio of those under `after`, Hessian
// positive definite), its
// largest vertex move is capped as a Newton step's is (max_displacement with a body), and the
// energy of `after` must fall along it (Armijo backtracking). With self-contact the step is
// bounded as the solver's straight steps are, so that no cloth layer passes through another
// (longest_layer_safe_step).
#pragma once

#include <string>

#include "sim/bisected_cholesky.h"
#include "sim/cloth_model.h"

namespace foldsketch {

struct PatternChangeSettings {
  // The start counts as an equilibrium of `before` when its forces there are at most this
  // fraction of its forces under `after` (2-norms): what the step responds to is the change.
  // A drape converged to the solver's tolerance has 1e-6 of the weight; the benchmark's stored
  // starts (float, their 0.1 um rounding strains the stiff membrane) about 0.1 of it, against
  // 100-250 of it after a 2-5 % widening; a start that is no equilibrium of either pattern
  // (a placement) has forces of the same size under both. Our choice between them.
  double max_force_ratio = 0.1;
  double max_displacement = 0.01;  // [m], as DrapeSettings::max_displacement
  // The old Hessian's factorisation, as DrapeSettings::factor_precision; a single-precision
  // solve not to be trusted (BisectedCholesky::last_solve_trusted) is redone in double.
  FactorPrecision factor_precision = FactorPrecision::Single;
};

struct PatternChangeStep {
  MatrixX3d V;             // the predicted drape (the start itself when not applied)
  bool applied = false;
  // The start passed the force test (max_force_ratio): an equilibrium of `before` as far as the
  // change can tell, whether or not the step was then taken (true whenever applied). A drape
  // the fast preset stopped at its re-drape budget passes it too (its forces 0.05-7 times its
  // weight, against 100-250 times after a 2-5 % change).
  bool near_equilibrium = false;
  std::string message;     // why not, when not applied
  double step_fraction = 0;  // of the predicted step, after the cap and the line search
  double step_length = 0;    // largest vertex move [m]
  double start_residual = 0; // relative force residual (as DrapeStats::residual) of the start under `before`
  double change_residual = 0; // and under `after`
  double seconds = 0;
};

// The predicted drape for `after` from x0, an equilibrium of `before`. The two models must be
// the same garment (vertices, triangles, pins, self-contact or not); only the rest shapes may
// differ. factorisation: where to factorise the old Hessian, when the caller wants its analysis
// kept for the re-drape (solve_drape's factorisation: the Hessian's pattern is the same for
// both patterns without self-contact; 0.3 s of analysis at 20K triangles). Without it the step
// uses its own.
PatternChangeStep predict_pattern_change(const ClothModel& before, const ClothModel& after, const MatrixX3d& x0,
                                         const PatternChangeSettings& settings = {},
                                         BisectedCholesky* factorisation = nullptr);

} // namespace foldsketch
