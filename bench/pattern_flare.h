// A local pattern change for the benchmark's re-drapes, in the pipeline's manner: extend-patterns
// adds width where folds are to form (hemline folds: more toward the hem, DESIGN.md section 3),
// where --ease widens the whole garment a little. Here each panel gets a flare let into its
// middle, as a pattern maker slashes a panel from the hem up to the waist and spreads it:
//
//   about the pivot (x_c, y_top), the top of the panel's middle ruling, a pattern point (u, v)
//   (u = x - x_c, v = y - y_top <= 0) turns by phi = theta clamp(u / h, -1, 1), with h a quarter
//   of the panel's width (its middle half spreads) and theta = flare h / L, L the panel's height.
//
// The outer quarters turn as rigid pieces, so every seam on them keeps its length and shape;
// the middle half fans out, the fan's width at depth |v| growing by 1 + flare |v| / L (so by
// 1 + flare at the hem). Both skirt panels get the same map, so the side seams still match.
#pragma once

#include "garment/garment.h"

namespace foldsketch {

// g with its patterns P flared as above (drape V unchanged); flare >= 0, as a share of the middle
// half's width added at the hem. Throws ArgumentError for a negative flare or a panel without
// height or width.
Garment flared_patterns(const Garment& g, double flare);

} // namespace foldsketch
