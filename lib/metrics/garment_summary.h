// What a person or a script wants to know about a garment before working on it: panels,
// seams with both sides' lengths, boundary runs, mesh quality, placement strain.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "garment/garment.h"
#include "garment/garment_issues.h"

namespace foldsketch {

struct RunSummary {
  double length = 0.0;        // pattern length [m]
  int vertices = 0;
  bool closed = false;
};

struct PanelSummary {
  std::string name;
  int triangles = 0;
  int vertices = 0;           // pattern vertices
  double area = 0.0;          // pattern area [m^2]
  double drape_area = 0.0;    // drape area [m^2]
  int loops = 0;              // boundary loops (1 + holes)
  std::vector<RunSummary> runs;  // boundary runs between corners, loop by loop
  double min_angle = 0.0;     // smallest pattern triangle angle [rad]
};

struct SeamSummary {
  int panel_a = -1, panel_b = -1;
  int vertices = 0;
  bool closed = false;
  double length_a = 0.0, length_b = 0.0;  // pattern lengths of both sides [m]
  double drape_length = 0.0;              // sewn length in the drape [m]
};

struct GarmentSummary {
  int triangles = 0, drape_vertices = 0, pattern_vertices = 0, stitches = 0;
  std::vector<PanelSummary> panels;
  std::vector<SeamSummary> seams;
  double min_angle = 0.0;                 // over all pattern triangles [rad]
  double mean_min_angle = 0.0;            // mean of the per-triangle smallest angle [rad]
  double min_stretch = 0.0, max_stretch = 0.0;  // principal stretches, drape vs pattern
  Eigen::AlignedBox3d drape_box;          // [m]
  GarmentIssues issues;
};

GarmentSummary garment_summary(const Garment& g);

} // namespace foldsketch
