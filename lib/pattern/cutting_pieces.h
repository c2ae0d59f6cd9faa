// Cutting pieces: what a cutting room needs of each panel. Cut line (the outline plus seam
// allowance), sew line, notches where seams must match, grain line, and which panels are cut
// from the same piece. Metres, pattern coordinates (x across, y up); writers convert to mm.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "garment/garment.h"
#include "garment/seams.h"
#include "pattern/congruent_panels.h"
#include "pattern/seam_allowance.h"

namespace foldsketch {

// A slit notch: a cut of length `depth` from `at` on the cut line along the unit vector `inward`.
struct Notch {
  Vector2d at = Vector2d::Zero();
  Vector2d inward = Vector2d::Zero();
  double depth = 0.0;
};

struct CuttingPiece {
  int panel = -1;
  std::string name;                    // the panel's name
  CutOutline cut;                      // cut line; its holes are internal cut-outs
  std::vector<Loop2> sew;              // the panel's boundary loops, outer first (material on the left)
  std::vector<Notch> notches;
  Vector2d grain_from = Vector2d::Zero(), grain_to = Vector2d::Zero();  // along the warp
  std::vector<std::vector<Vector2d>> internal_lines;  // drawn, not cut (pleat fold lines)
  std::vector<Vector2d> drill_holes;                   // punched (pleat ends)
  std::optional<int> partner;          // index of the piece cut from the same pattern
  PanelMatch partner_match = PanelMatch::Copy;
  // Pieces cut from this pattern: 1, or 2 when merge_congruent_pieces() folded the partner in
  // (then `merged` names the partner's panel and `partner_match` says copy or mirror image).
  int quantity = 1;
  std::string merged;
};

struct PieceParams {
  AllowanceParams allowance;
  // Notch depth [m]: 6 mm (1/4 inch), the common industrial slit notch; never deeper than the
  // allowance when there is one.
  double notch_depth = 0.006;
  // Seams at least this long [m] get a balance notch at the middle of side a and at the
  // corresponding vertex of side b (the same drape point), besides the notches at their ends.
  double balance_notch_length = 0.15;
  // The grain line spans this fraction of the piece's chord along the warp through its centroid.
  double grain_fraction = 0.7;
  // Outlines congruent within this RMS distance [m] are cut from one pattern (0.1 mm).
  double pair_tolerance = 1e-4;
};

struct CuttingLayout {
  std::vector<CuttingPiece> pieces;    // one per panel, in panel order
  std::vector<BoundaryLoop> loops;     // panel_boundaries() of the garment
  std::vector<Seam> seams;             // seams() of the garment
};

// Pieces of every panel of g. The grain line runs along pattern y: the warp of our material
// model (lib/sim/membrane.h), so the cut piece and the simulated one agree; a bias-cut panel
// is a panel rotated in pattern space. Throws ArgumentError when a panel's outline cannot be
// offset (see seam_allowance()).
CuttingLayout cutting_pieces(const Garment& g, const PieceParams& params = {});

// One piece per pair of congruent pieces, as a cutting room wants them: the lower-indexed piece
// of each pair with quantity 2 ("cut 2" for copies, "cut pair" for mirror images), the other
// dropped. Unpaired pieces are kept as they are. Order is kept.
std::vector<CuttingPiece> merge_congruent_pieces(const std::vector<CuttingPiece>& pieces);

} // namespace foldsketch
