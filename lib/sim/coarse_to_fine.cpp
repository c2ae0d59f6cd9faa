#include "sim/coarse_to_fine.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "garment/coarse_garment.h"
#include "garment/drape_transfer.h"

namespace foldsketch {

std::vector<int> coarse_levels(int triangles, const CoarseToFineSettings& settings) {
  std::vector<int> levels;
  for (double t = triangles / settings.level_ratio; t >= settings.min_triangles; t /= settings.level_ratio)
    levels.insert(levels.begin(), static_cast<int>(std::lround(t)));
  return levels;
}

CoarseToFineResult solve_drape_coarse_to_fine(const Garment& garment, const Scene& scene, const TriangleMesh* body,
                                              const ClothModel& model, const MatrixX3d& initial, const DrapeSettings& settings,
                                              const std::vector<int>& level_triangles, const DrapeProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (scene.physics.self_contact)
    throw ArgumentError("coarse-to-fine draping: the scene asks for self-contact, which needs the garment's own mesh throughout");
  // A coarse outline vertex is an original vertex; this close to one it is that vertex [m]
  // (transfer_drape carries it over up to roundoff).
  constexpr double kSameVertex = 1e-9;

  CoarseToFineResult out;
  Garment placed = garment;
  placed.V = initial;
  Garment previous;        // the level before, and its drape
  MatrixX3d previous_drape;
  for (size_t level = 0; level <= level_triangles.size(); ++level) {
    const bool finest = level == level_triangles.size();
    DrapeSettings level_settings = settings;
    if (level > 0) level_settings.membrane_fallback = false;  // see the header
    if (finest) {
      const MatrixX3d from = level > 0 ? transfer_drape(previous, previous_drape, garment) : initial;
      out.drape = solve_drape(model, from, level_settings, progress);
      out.levels.push_back({static_cast<int>(model.triangles.size()), out.drape.stats});
      break;
    }
    Garment coarse = coarse_garment(placed, spacing_for_triangles(placed, level_triangles[level]));
    // Pins: the scene's boxes on the coarse drape, and the model's pinned vertices the outline kept.
    Scene boxes_only = scene;
    for (VertexSelector& s : boxes_only.pins) s.vertices.clear();
    std::vector<int> pinned = pinned_vertices(boxes_only, coarse.V);
    for (const Pin& p : model.pins) {
      int nearest = -1;
      double distance = kSameVertex;
      for (int v = 0; v < coarse.V.rows(); ++v) {
        const double d = (coarse.V.row(v).transpose() - p.position).norm();
        if (d <= distance) distance = d, nearest = v;
      }
      if (nearest < 0) continue;
      coarse.V.row(nearest) = p.position.transpose();
      pinned.push_back(nearest);
    }
    std::sort(pinned.begin(), pinned.end());
    pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
    if (!model.pins.empty() && pinned.empty())
      throw ArgumentError("coarse-to-fine draping: no vertex of the " + std::to_string(level_triangles[level]) +
                          "-triangle level falls on a pin");
    const ClothModel coarse_model = cloth_model(coarse, scene, body, pinned);
    const MatrixX3d from = level > 0 ? transfer_drape(previous, previous_drape, coarse) : coarse.V;
    DrapeResult drape = solve_drape(coarse_model, from, level_settings, progress);
    out.levels.push_back({static_cast<int>(coarse_model.triangles.size()), drape.stats});
    previous = std::move(coarse);
    previous_drape = std::move(drape.V);
  }
  out.seconds_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace foldsketch
