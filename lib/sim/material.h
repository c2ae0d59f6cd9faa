// Fabric materials in SI units, and the named presets scenes refer to.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace foldsketch {

struct Material {
  std::string name;        // preset name, or "custom"
  double density = 0.0;        // area density [kg/m^2]
  double stretch_warp = 0.0;   // uniaxial tensile stiffness along the grain (pattern y) [N/m]
  double stretch_weft = 0.0;   // uniaxial tensile stiffness across the grain (pattern x) [N/m]
  double shear = 0.0;          // in-plane shear stiffness [N/m]
  double poisson = 0.0;        // in-plane Poisson ratio [-]
  double bending = 0.0;        // bending stiffness D [N m]
  std::string source;          // where the numbers come from

  // Bending length c = (D / (rho g))^(1/3) [m] (Peirce), the length scale of folds.
  double bending_length(double gravity = 9.81) const;
};

// Names of the presets, in a fixed order.
std::vector<std::string> material_preset_names();

// The preset called name, or nothing.
std::optional<Material> material_preset(const std::string& name);

// Empty when m is physically usable, else what is wrong (non-positive or non-finite values).
std::string material_error(const Material& m);

} // namespace foldsketch
