// A garment on disk: NAME.obj plus, when it has stitches, the sidecar NAME.stitches.xml.
#pragma once

#include <string>

#include "garment/garment.h"

namespace foldsketch {

// The sidecar path of a garment OBJ path: "dir/skirt.obj" -> "dir/skirt.stitches.xml".
std::string stitches_path(const std::string& garment_path);

// Read the OBJ and its sidecar if present; check stitches against the garment.
Garment read_garment(const std::string& path);

// Write the sidecar (when g has stitches; a stale sidecar at the output is removed otherwise),
// then the OBJ, each atomically. path "-" writes the OBJ to standard output (no sidecar).
void write_garment(const Garment& g, const std::string& path);

} // namespace foldsketch
