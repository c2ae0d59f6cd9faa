// Garment OBJ (formats/garment-obj.md): v = drape [m], vt = pattern [m], one g (or o) group
// per panel, faces f v/vt. Also reads the ARCSim / Berkeley Garment Library convention (one vt
// per face corner, vv and t lines, panels = connected components in pattern space).
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "garment/garment.h"

namespace foldsketch {

// Parse a garment OBJ from `in`; `path` names it in messages. Throws InputError
// "path:line: message" quoting the bad token. Stitches are not in the OBJ (see garment_io.h).
Garment parse_garment_obj(std::istream& in, const std::string& path);
Garment read_garment_obj(const std::string& path);

// Write g (stitches excluded) so that parse_garment_obj returns it exactly.
void print_garment_obj(const Garment& g, std::ostream& out);

} // namespace foldsketch
