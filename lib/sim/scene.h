// What a scene asks for: which garment on which body, in which fabric, under which physics
// and solver settings. Paths are as written in the scene file, relative to it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/types.h"
#include "sim/material.h"

namespace foldsketch {

// Drape vertices (to pin, or where self-contact acts): those inside a box, and/or listed
// (0-based here, 1-based in files).
struct VertexSelector {
  std::optional<Eigen::AlignedBox3d> box;
  std::vector<int> vertices;
};

// The physics a scene needs; the engine assembles only these terms.
struct PhysicsSwitches {
  bool body_contact = true;   // one-sided contact with the body mesh
  bool self_contact = false;  // cloth-cloth contact (pleats)
  bool friction = false;      // friction against the body
  bool hemline = false;       // tangential hemline design term (thesis ch. 6)
};

enum class SimulationMode { Static, Dynamic };
enum class SolverPreset { Accurate, Fast };

struct SimulatorSettings {
  SimulationMode mode = SimulationMode::Static;
  SolverPreset preset = SolverPreset::Accurate;
  double time_step = 0.01;    // [s]; our default, the engine adapts it
  // Newton iterations (static) or time steps (dynamic) before giving up. A safeguard, not a
  // stopping rule: a static drape stops by itself at the tolerance or when no step lowers the
  // energy. Measured cold drapes take up to 1092 iterations (silk skirt, 10K triangles) and
  // 976 (thin cotton, 54K; bench/drape_bench.txt), so the limit leaves about 5x headroom.
  int max_steps = 5000;
  double tolerance = 1e-6;    // relative force residual at which a static drape has converged
};

struct BodySettings {
  std::string file;
  double thickness = 0.002;   // contact offset from the body surface [m]; our default
};

struct Scene {
  std::string name;
  std::string garment_file;
  std::optional<BodySettings> body;
  Material material;
  Vector3d gravity{0.0, -9.81, 0.0};  // [m/s^2]; y up as in the bodies we ship
  PhysicsSwitches physics;
  std::vector<VertexSelector> pins;
  // Where self-contact acts ("near the pleats"), when physics.self_contact; none: everywhere.
  std::vector<VertexSelector> self_contact_regions;
  SimulatorSettings simulator;
};

const char* to_string(SimulationMode mode);
const char* to_string(SolverPreset preset);

} // namespace foldsketch
