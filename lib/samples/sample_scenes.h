// The sample scenes, made by code so that any resolution can be produced:
//   flag       one 1.0 x 0.6 m panel pinned along its pole edge, beside a pole
//   skirt      front and back A-line panels sewn at the side seams, waist pinned, on a body
//   box-cover  a top and four side panels sewn along the edges of a box
//   dress      strapless dress: two bodice and two skirt panels, curved waist seams, on a body
// The drape is the sewn placement (isometric to the patterns, clear of the body), not yet a
// simulated drape.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "garment/garment.h"
#include "mesh/primitive_meshes.h"
#include "sim/scene.h"

namespace foldsketch {

enum class SampleMesh {
  Grid,       // structured cells split by alternating diagonals
  Isotropic   // jittered hexagonal lattice, grid boundary kept (better for hinge bending)
};

struct SampleParams {
  int triangles = 10000;        // target triangle count; the result is within a few percent
  SampleMesh mesh = SampleMesh::Grid;
  double clearance = 0.01;      // gap between body and placed garment [m]; our choice
  double waist_to_hem = 0.55;   // skirt length [m]: natural waist to just above the knee
  double dress_waist_to_hem = 0.65;
  double bodice_height = 0.08;  // dress bodice above the natural waist [m], below the armpits
  double min_flare = 0.2;       // A-line: hem axes at least (1 + min_flare) times the waist's
};

struct SampleScene {
  Garment garment;
  std::optional<TriangleMesh> body;  // generated body (pole, box); empty for a given body
  Scene scene;                       // garment_file / body file left for the caller to set
};

// Names of the samples, in a fixed order.
std::vector<std::string> sample_names();

// Whether the sample is fitted around a given human body mesh (y up, metres, facing +z).
bool sample_needs_body(const std::string& name);

// The sample called name; body_V is the body's vertices (#V by 3), required when
// sample_needs_body(name). Throws ArgumentError for an unknown name.
SampleScene make_sample(const std::string& name, const SampleParams& params, const MatrixX3d* body_V = nullptr);

} // namespace foldsketch
