// Geometric and topological problems of a structurally sound garment, reported (never
// thrown): a tool decides whether a problem stops it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "garment/garment.h"

namespace foldsketch {

struct IssueParams {
  // A triangle is degenerate when its double area is at most this times its longest edge
  // squared, i.e. its smallest angle is below about 1e-10 rad: no stable rest shape exists.
  double degenerate_relative_area = 1e-10;
  // A triangle is a sliver when its smallest angle is below this [rad]; 10 degrees is where
  // linear-triangle cloth elements start to lock (our choice, to be measured by the engine).
  double sliver_angle = 10.0 * 3.14159265358979323846 / 180.0;
};

struct GarmentIssues {
  std::vector<int> nonfinite_drape_vertices;       // V rows with NaN or Inf
  std::vector<int> nonfinite_pattern_vertices;     // P rows with NaN or Inf
  std::vector<int> degenerate_pattern_faces;       // no usable rest shape
  std::vector<int> degenerate_drape_faces;         // collapsed in the drape
  std::vector<int> sliver_pattern_faces;           // poor rest shape (min angle below sliver_angle)
  std::vector<int> flipped_pattern_faces;          // orientation against the majority of the panel
  std::vector<std::array<int, 2>> nonmanifold_pattern_edges;  // pattern edges of 3+ triangles
  std::vector<std::array<int, 2>> nonmanifold_drape_edges;    // drape edges of 3+ triangles
  std::vector<std::array<int, 2>> misoriented_drape_edges;    // two triangles walk it the same way
  std::string drape_scale;  // drape_scale_error(): patterns in other units than the drape; empty when none

  bool empty() const;
  // One line per kind of problem, counting and naming the first few (1-based, as in the OBJ).
  std::vector<std::string> messages() const;
};

GarmentIssues garment_issues(const Garment& g, const IssueParams& params = {});

} // namespace foldsketch
