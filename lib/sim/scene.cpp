#include "sim/scene.h"

namespace foldsketch {

const char* to_string(SimulationMode mode) { return mode == SimulationMode::Static ? "static" : "dynamic"; }
const char* to_string(SolverPreset preset) { return preset == SolverPreset::Accurate ? "accurate" : "fast"; }

} // namespace foldsketch
