// Stitch sidecar XML (formats/stitches-xml.md): sewing that welded vertices cannot express.
#pragma once

#include <string>
#include <vector>

#include "garment/garment.h"

namespace foldsketch {

struct LocatedStitch {
  Stitch stitch;
  int line = 0;  // where it was read, for messages
};

// Read the stitches of a sidecar; vertex numbers are 1-based in the file, 0-based here.
// Ranges are checked against the garment by read_garment().
std::vector<LocatedStitch> read_stitches_xml(const std::string& path);

std::string stitches_xml_text(const std::vector<Stitch>& stitches);

} // namespace foldsketch
