#include "sim/coarse_to_fine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

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

CoarseToFineResult solve_drape_coarse_to_fine(const Garment& garment, const Scene& scene, const ClothModel& model,
                                              const MatrixX3d& initial, const DrapeSettings& settings,
                                              const std::vector<int>& level_triangles, const DrapeProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (scene.physics.self_contact)
    throw ArgumentError("coarse-to-fine draping: the scene asks for self-contact, which needs the garment's own mesh throughout");
  CoarseToFineResult out;
  Garment placed = garment;
  placed.V = initial;
  // Coarse levels are pinned by the scene's boxes and at the model's pinned vertices their
  // outline keeps, held exactly where the model holds them.
  Scene boxes_only = scene;
  for (VertexSelector& s : boxes_only.pins) s.vertices.clear();
  std::unordered_map<int, const Pin*> pin_of;
  for (const Pin& p : model.pins) pin_of[p.vertex] = &p;
  DrapeSettings finer_settings = settings;  // every level after the first
  finer_settings.membrane_fallback = false;  // see the header
  Garment previous;  // the level before, and its drape
  MatrixX3d previous_drape;
  for (size_t level = 0; level < level_triangles.size(); ++level) {
    VectorXi original;  // the original drape vertex of each kept coarse vertex, else -1
    Garment coarse = coarse_garment(placed, spacing_for_triangles(placed, level_triangles[level]), &original);
    std::vector<int> pinned = pinned_vertices(boxes_only, coarse.V);
    for (int v = 0; v < coarse.V.rows(); ++v) {
      const auto it = original(v) >= 0 ? pin_of.find(original(v)) : pin_of.end();
      if (it == pin_of.end()) continue;
      coarse.V.row(v) = it->second->position.transpose();
      pinned.push_back(v);
    }
    std::sort(pinned.begin(), pinned.end());
    pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
    if (!model.pins.empty() && pinned.empty())
      throw ArgumentError("coarse-to-fine draping: no vertex of the " + std::to_string(level_triangles[level]) +
                          "-triangle level falls on a pin");
    const ClothModel coarse_model = cloth_model_on(coarse, scene, model.body, pinned);
    const MatrixX3d from = level > 0 ? transfer_drape(previous, previous_drape, coarse) : coarse.V;
    DrapeResult drape = solve_drape(coarse_model, from, level > 0 ? finer_settings : settings, progress);
    out.levels.push_back({static_cast<int>(coarse_model.triangles.size()), drape.stats});
    previous = std::move(coarse);
    previous_drape = std::move(drape.V);
  }
  // The garment's own mesh, from the last coarse level (or from the start when there is none).
  const bool coarse_before = !level_triangles.empty();
  const MatrixX3d from = coarse_before ? transfer_drape(previous, previous_drape, garment) : initial;
  out.drape = solve_drape(model, from, coarse_before ? finer_settings : settings, progress);
  out.levels.push_back({static_cast<int>(model.triangles.size()), out.drape.stats});
  out.seconds_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace foldsketch
