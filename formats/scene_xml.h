// scene.xml (formats/scene-xml.md): garment, body, material, gravity, physics, pins, solver.
#pragma once

#include <string>

#include "sim/scene.h"

namespace foldsketch {

// Read and check a scene. File references are resolved against the scene's folder and must
// exist; a reference that does not is reported at its line of the scene file.
Scene read_scene_xml(const std::string& path);

// The path of a file named in a scene, resolved against the scene file's folder.
std::string scene_relative(const std::string& scene_path, const std::string& file);

std::string scene_xml_text(const Scene& scene);
void write_scene_xml(const Scene& scene, const std::string& path);

} // namespace foldsketch
