// Panels that a cutting room cuts from the same pattern piece: copies (congruent by a rotation
// and translation: "cut 2") and mirror images (congruent only through a reflection: "cut a pair",
// one face up and one face down, as the left and right halves of a garment).
#pragma once

#include <vector>

#include "pattern/seam_allowance.h"

namespace foldsketch {

enum class PanelMatch { Copy, Mirror };

struct PanelPair {
  int a = -1, b = -1;       // a < b
  PanelMatch match = PanelMatch::Copy;
  double rms = 0.0;         // RMS vertex distance after the best rigid fit [m]
};

// Pairs among `outlines` (one outer loop per panel, counter-clockwise) whose vertices correspond
// one to one, in order, within an RMS distance of `tolerance` [m] after the best rotation (and,
// for Mirror, reflection) and translation. Outlines sampled differently are never paired: the
// test is on vertices, so it cannot call two merely similar curves equal. Each panel is in at most
// one pair; a copy is preferred to a mirror image (a symmetric piece is both), lower indices first.
std::vector<PanelPair> congruent_panels(const std::vector<Loop2>& outlines, double tolerance);

} // namespace foldsketch
