// How large the drape is against its patterns: the check that catches patterns written in
// other units than the drape (millimetres, centimetres, inches, or texture coordinates in vt),
// which no simulation can drape.
#pragma once

#include <string>

#include "garment/garment.h"

namespace foldsketch {

// A drape on median more than this many times larger or smaller than its patterns (linear
// size) is taken for a units mistake. Real placements stay well inside: the Berkeley Garment
// Library skirt, "stretched around the figure in a highly distorted fashion" (its README),
// has principal stretches of 0.58-1.45; the mistakes it catches are factors of 10, 25.4, 39.4,
// 100 and 1000 (cm, inches and mm against metres either way). Our choice between them.
constexpr double kLargestPlausibleDrapeScale = 3.0;

// Median over the triangles of sqrt(drape area / pattern area); 1 for a drape at its pattern
// size. Triangles degenerate in either shape are left out; NaN when none is left.
double median_drape_scale(const Garment& g);

// Empty when the drape's median scale is within kLargestPlausibleDrapeScale of the patterns',
// else what is wrong and what to do, in words for the user.
std::string drape_scale_error(const Garment& g);

} // namespace foldsketch
