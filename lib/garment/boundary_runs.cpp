#include "garment/boundary_runs.h"

#include <algorithm>
#include <cmath>

namespace foldsketch {

std::vector<std::vector<int>> boundary_corners(const Garment& g, const std::vector<BoundaryLoop>& loops,
                                               const std::vector<Seam>& seams, const CornerParams& params) {
  std::vector<std::vector<int>> corners(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& v = loops[l].vertices;
    const int n = static_cast<int>(v.size());
    for (int i = 0; i < n; ++i) {
      const Vector2d in = g.P.row(v[i]) - g.P.row(v[(i + n - 1) % n]);
      const Vector2d out = g.P.row(v[(i + 1) % n]) - g.P.row(v[i]);
      const double turning = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
      if (std::abs(turning) > params.min_turning) corners[l].push_back(i);
    }
  }
  const auto add_end = [&](const SeamSide& side, int vertex) {
    const auto& v = loops[side.loop].vertices;
    const auto it = std::find(v.begin(), v.end(), vertex);
    if (it != v.end()) corners[side.loop].push_back(static_cast<int>(it - v.begin()));
  };
  for (const Seam& s : seams) {
    if (s.closed) continue;
    for (const SeamSide* side : {&s.a, &s.b}) {
      add_end(*side, side->vertices.front());
      add_end(*side, side->vertices.back());
    }
  }
  for (auto& c : corners) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  return corners;
}

std::vector<BoundaryRun> boundary_runs(const std::vector<BoundaryLoop>& loops,
                                       const std::vector<std::vector<int>>& corners) {
  std::vector<BoundaryRun> runs;
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& v = loops[l].vertices;
    const int n = static_cast<int>(v.size());
    const auto& c = corners[l];
    if (c.empty()) {
      runs.push_back({static_cast<int>(l), v, true});
      continue;
    }
    for (size_t k = 0; k < c.size(); ++k) {
      const int from = c[k], to = c[(k + 1) % c.size()];
      const int count = ((to - from) % n + n) % n;
      BoundaryRun run{static_cast<int>(l), {}, false};
      for (int i = 0; i <= (count == 0 ? n : count); ++i) run.vertices.push_back(v[(from + i) % n]);
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

} // namespace foldsketch
