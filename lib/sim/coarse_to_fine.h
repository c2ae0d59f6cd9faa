// Draping coarse to fine: the garment's patterns remeshed at a few coarser resolutions
// (garment/coarse_garment.h); the coarsest level drapes from the start, each finer level from
// the level before (carried over by transfer_drape), the garment's own mesh last.
//
// Why: a cold drape (from a placement) spends most of its Newton iterations forming folds (the
// 20K grid skirt's mean distance to its end is still 2 mm after 289 of 363 iterations,
// bench/drape_bench.txt), and on a coarse mesh an iteration costs a fraction. The fine level
// then starts from the coarse folds. Measured on the benchmark skirt, 3 paths each (bench/
// drape_bench.txt, session 42): on its isotropic mesh (the samples' meshing) 1.6 and 2.8 times
// faster at 10K and 20K triangles and as fast at 54K (one path; 1.5 times in session 31); on
// its grid mesh, where the stress-weighted step metric made the plain cold drapes short, 1.5
// times faster at 20K but 3.1 times slower at 10K and 54K. What limits it: the fine level still takes 190-560
// Newton iterations. Its start is the coarse level's equilibrium, whose folds are not the fine
// mesh's (isotropic 20K from 5K: 6.6 mm mean from where the fine level ends), and the fine level
// settles its own folds in Newton steps of 0.1-1 mm. The fine triangles that straddle coarse
// creases are squeezed too (to 0.8 of their pattern size), but relaxing them first
// (as-rigid-as-possible, to 0.98) saved only 2-6 % of the fine iterations (bench/drape_bench.txt,
// session 38); nor did more levels help, each spends 100-250 iterations on its own folds. Meant
// for cold drapes: a start that already holds the fine drape's folds loses them on the coarse
// level. After a change that forms new folds (a 20 % flare let into each skirt panel,
// bench/pattern_flare.h) it was 1.0-2.5 times faster than the plain re-drape on the grid skirt
// at 20K triangles, but 0.7-1.2 times at 10K and 0.8-1.1 times on the isotropic skirt
// (bench/drape_bench.txt, session 43).
//
// Its drape depends far less on the start than a plain cold drape does (bench/drape_bench.txt,
// session 38; bench/cold_paths.sh): from the sewn placement and the placement moved by up to
// 1 um (two seeds), the skirt's drapes ended 0.004-0.07 mm mean apart (once 1.49 mm) on the
// grid and isotropic meshes at 10K and 20K triangles, where the plain cold drapes ended 2.8-13.4
// mm apart. So a batch job that re-runs a cold drape from a placement that moved by a rounding
// gets the same garment back.
//
// Every level after the first runs without the membrane fallback (DrapeSettings::
// membrane_fallback): the carried-over drape squeezes some fine triangles to 0.6-0.7 of their
// pattern size where the coarse mesh cut across a fold, which switches the fallback on, though
// the drape is near an equilibrium and the exact Hessian's buckling directions are what the
// fine level needs. Measured on the 20K skirt from 5K (3 seeds): fine level 155 / 145 / 278
// Newton iterations without the fallback against 194 / 416 / 510 with it, 144 of the 194 on
// projected elements.
#pragma once

#include <vector>

#include "garment/garment.h"
#include "mesh/primitive_meshes.h"
#include "sim/cloth_model.h"
#include "sim/drape_solver.h"
#include "sim/scene.h"

namespace foldsketch {

struct CoarseToFineSettings {
  // Each level has about 1/level_ratio of the triangles of the level above it, and the
  // coarsest at least min_triangles: our choice, the only rule measured (above). A level of
  // half the triangles damages less in the carrying (a finished 10K drape through 5K took 135
  // iterations to repair, through 2.5K 196) but costs more to drape.
  double level_ratio = 4.0;
  int min_triangles = 2000;
};

// Triangle counts of the coarse levels for a garment of `triangles` triangles, coarsest first;
// empty when even the first level would have fewer than min_triangles.
std::vector<int> coarse_levels(int triangles, const CoarseToFineSettings& settings = {});

struct DrapeLevel {
  int triangles = 0;
  DrapeStats stats;
};

struct CoarseToFineResult {
  DrapeResult drape;               // the garment's own mesh (the last level)
  std::vector<DrapeLevel> levels;  // every level, coarsest first, the garment's own last
  double seconds_total = 0;        // all levels, remeshing and carrying over included
};

// Drapes `model` (built from `garment` and `scene`; its body's distance structure serves every
// level) from `initial` through coarse levels of level_triangles triangles (coarsest first).
// Coarse levels are pinned where the scene's pin boxes select, and at the model's pinned
// vertices that the coarse outline keeps. progress is called for every level's steps (with
// that level's drape). Throws ArgumentError for a garment the coarse meshing refuses (explicit
// stitches), a scene with self-contact, or pins that no coarse vertex takes.
CoarseToFineResult solve_drape_coarse_to_fine(const Garment& garment, const Scene& scene, const ClothModel& model,
                                              const MatrixX3d& initial, const DrapeSettings& settings,
                                              const std::vector<int>& level_triangles, const DrapeProgress& progress = {});

} // namespace foldsketch
