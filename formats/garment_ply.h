// Garment export for viewers (MeshLab, Blender, any PLY reader): the drape with one colour per
// panel. Seam vertices appear once per panel, so panels keep crisp colours.
#pragma once

#include <string>

#include "garment/garment.h"

namespace foldsketch {

std::string garment_ply_text(const Garment& g);
void write_garment_ply(const Garment& g, const std::string& path);

} // namespace foldsketch
