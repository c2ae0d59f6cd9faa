// Everything the cloth engine needs about one garment in one scene, computed once: rest shapes
// from the patterns, lumped masses, hinges (across seams too), stitches, pins, and only those
// terms the scene's physics asks for.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "garment/garment.h"
#include "garment/pins.h"
#include "sim/body_distance.h"
#include "sim/membrane.h"
#include "sim/scene.h"
#include "sim/self_contact.h"

namespace foldsketch {

struct ClothParams {
  // Penalty stiffness of body contact [N/m^3]: a garment of area density rho resting on the
  // body sinks rho g / k into the contact layer, 1.5 um for cotton and 3 um for denim, far
  // below the 0.5 mm penetration budget, while k times a vertex area (about 1e-4 m^2 at 10K
  // triangles) stays near the membrane stiffness and keeps Newton well conditioned.
  double contact_stiffness = 1e6;
  // Zero-length stitch springs, as a multiple of the material's largest stretch stiffness
  // [N/m per N/m]: a stitch gap of 1 % of the membrane strain at equal force.
  double stitch_stiffness_factor = 100.0;
  // Cloth-cloth contact, when the scene asks for it. Thickness [m]: the distance a vertex is
  // held from another layer, about three thicknesses of cotton (Penava et al. 2014: 0.318 mm),
  // so that layers also stay apart between the vertices of 5-10 mm meshes; our choice.
  // Stiffness [N/m^3]: the body contact's, for the same reason (a layer of cotton sinks 1.5 um).
  double self_contact_thickness = 0.001;
  double self_contact_stiffness = 1e6;
  // Drape vertices that take part ("near the pleats"), with those of the scene's
  // self-contact regions; both empty: all of them.
  std::vector<int> self_contact_vertices;
};

struct Hinge {
  std::array<int, 4> v;  // edge v0-v1; v2 on the triangle walking v0 -> v1, v3 on the other
  double stiffness = 0;  // k of k (theta - theta0)^2 [J]
  double rest_angle = 0; // patterns are flat: 0
};

struct StitchSpring {
  std::array<int, 4> v;       // a0, a1, b0, b1 (a1 or b1 may repeat a0/b0 with weight 0)
  std::array<double, 4> w;    // point a = w0 x_a0 + w1 x_a1, b = -(w2 x_b0 + w3 x_b1)
};

struct ClothModel {
  int vertex_count = 0;
  VectorXd mass;                                 // lumped, #V [kg]
  std::vector<std::array<int, 3>> triangles;     // drape vertex indices
  std::vector<MembraneRest> rest;                // per triangle
  MembraneStiffness stiffness;
  std::vector<Hinge> hinges;                     // empty when the material has no bending
  std::vector<StitchSpring> stitches;
  double stitch_stiffness = 0;                   // [N/m]
  Vector3d gravity = Vector3d::Zero();           // [m/s^2]
  std::vector<Pin> pins;                         // held exactly (their DOFs are eliminated)
  // Only when the scene asks for body contact. Shared by the models of one garment on one body
  // (a re-drape's old and new patterns, coarse-to-fine levels): built once, 0.08-0.1 s for the
  // 47K-triangle sample body.
  std::shared_ptr<const BodyDistance> body;
  std::optional<SelfContactModel> self_contact;  // only when the scene asks for self-contact
  double contact_thickness = 0;                  // [m]
  double contact_stiffness = 0;                  // [N/m^3]
  VectorXd contact_area;                         // per vertex rest area share [m^2]
  Material material;
};

// Build the model. `pinned` are drape vertices held at their positions in g.V. Throws
// InputError-free ArgumentError on structural problems; degenerate pattern triangles (no rest
// shape) are an error naming the first one.
ClothModel cloth_model(const Garment& g, const Scene& scene, const TriangleMesh* body, const std::vector<int>& pinned,
                       const ClothParams& params = {});
// The same on a body whose distance structure is already built (another model's `body`).
ClothModel cloth_model_on(const Garment& g, const Scene& scene, std::shared_ptr<const BodyDistance> body,
                          const std::vector<int>& pinned, const ClothParams& params = {});

// Drape vertices selected by the scene's pins, for garment drape V (sorted, unique). Throws
// ArgumentError when a pin names a vertex V does not have.
std::vector<int> pinned_vertices(const Scene& scene, const MatrixX3d& V);

// Drape vertices in the scene's self-contact regions, for garment drape V (sorted, unique;
// empty when the scene names none, meaning everywhere).
std::vector<int> self_contact_region(const Scene& scene, const MatrixX3d& V);

} // namespace foldsketch
