#include "sim/cloth_model.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "mesh/mesh_edges.h"
#include "sim/bending.h"

namespace foldsketch {

namespace {
// what: "a pin", "a self-contact region", for the message.
std::vector<int> selected_vertices(const std::vector<VertexSelector>& selectors, const MatrixX3d& V, const char* what) {
  std::vector<int> out;
  for (const VertexSelector& p : selectors) {
    if (p.box)
      for (int v : vertices_in_box(V, *p.box)) out.push_back(v);
    for (int v : p.vertices) {
      if (v < 0 || v >= V.rows())
        throw ArgumentError(std::string(what) + " names drape vertex " + std::to_string(v + 1) + " but the garment has " +
                            std::to_string(V.rows()));
      out.push_back(v);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}
} // namespace

std::vector<int> pinned_vertices(const Scene& scene, const MatrixX3d& V) { return selected_vertices(scene.pins, V, "a pin"); }

std::vector<int> self_contact_region(const Scene& scene, const MatrixX3d& V) {
  return selected_vertices(scene.self_contact_regions, V, "a self-contact region");
}

namespace {

// Who takes part in self-contact, and which pairs are never pushed apart: a vertex and the
// triangles around it, and across a seam the triangles around the vertices stitched to it.
SelfContactModel self_contact_model(const ClothModel& m, const ClothParams& params, const std::vector<int>& region) {
  SelfContactModel sc;
  sc.thickness = params.self_contact_thickness;
  sc.stiffness = params.self_contact_stiffness;
  std::vector<int> chosen = params.self_contact_vertices;
  chosen.insert(chosen.end(), region.begin(), region.end());
  std::vector<char> taking_part(static_cast<size_t>(m.vertex_count), chosen.empty() ? 1 : 0);
  for (int v : chosen) {
    if (v < 0 || v >= m.vertex_count) throw ArgumentError("cloth_model: self-contact vertex " + std::to_string(v) + " does not exist");
    taking_part[static_cast<size_t>(v)] = 1;
  }
  for (int v = 0; v < m.vertex_count; ++v)
    if (taking_part[static_cast<size_t>(v)]) sc.vertices.push_back(v);
  for (const auto& t : m.triangles) {
    if (!taking_part[static_cast<size_t>(t[0])] || !taking_part[static_cast<size_t>(t[1])] || !taking_part[static_cast<size_t>(t[2])]) continue;
    sc.triangles.push_back(t);
    for (int k = 0; k < 3; ++k) sc.edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  }
  std::sort(sc.edges.begin(), sc.edges.end());
  sc.edges.erase(std::unique(sc.edges.begin(), sc.edges.end()), sc.edges.end());
  sc.near.assign(static_cast<size_t>(m.vertex_count), {});
  for (int v = 0; v < m.vertex_count; ++v) sc.near[static_cast<size_t>(v)].push_back(v);
  for (const StitchSpring& s : m.stitches)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) sc.near[static_cast<size_t>(s.v[i])].push_back(s.v[j]);
  for (auto& near : sc.near) {
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
  }
  return sc;
}

} // namespace

ClothModel cloth_model(const Garment& g, const Scene& scene, const TriangleMesh* body, const std::vector<int>& pinned,
                       const ClothParams& params) {
  std::shared_ptr<const BodyDistance> distance;
  if (scene.physics.body_contact && body) distance = std::make_shared<const BodyDistance>(*body);
  return cloth_model_on(g, scene, std::move(distance), pinned, params);
}

ClothModel cloth_model_on(const Garment& g, const Scene& scene, std::shared_ptr<const BodyDistance> body,
                          const std::vector<int>& pinned, const ClothParams& params) {
  if (const std::string error = garment_structure_error(g); !error.empty()) throw ArgumentError("cloth_model: " + error);
  // Said plainly rather than silently simulated without: these terms are not built yet.
  if (scene.physics.friction) throw ArgumentError("the scene asks for friction, which the engine does not model yet");
  ClothModel m;
  m.vertex_count = static_cast<int>(g.V.rows());
  m.material = scene.material;
  m.stiffness = membrane_stiffness(scene.material);
  m.gravity = scene.gravity;
  m.mass = VectorXd::Zero(m.vertex_count);
  m.contact_area = VectorXd::Zero(m.vertex_count);
  for (int f = 0; f < g.F.rows(); ++f) {
    const MembraneRest r = membrane_rest(g.P.row(g.FP(f, 0)), g.P.row(g.FP(f, 1)), g.P.row(g.FP(f, 2)));
    if (!(r.area > 0.0) || !r.Dm_inverse.allFinite())
      throw ArgumentError("pattern triangle " + std::to_string(f + 1) + " is degenerate (zero area): it has no rest shape");
    m.triangles.push_back({g.F(f, 0), g.F(f, 1), g.F(f, 2)});
    m.rest.push_back(r);
    for (int k = 0; k < 3; ++k) {
      m.mass(g.F(f, k)) += scene.material.density * r.area / 3.0;
      m.contact_area(g.F(f, k)) += r.area / 3.0;
    }
  }

  // Hinges on every drape edge with exactly two consistently oriented triangles, seams included.
  const MeshEdges edges = mesh_edges(g.F, m.vertex_count);
  for (int e = 0; e < edges.E.rows(); ++e) {
    if (edges.faces[e].size() != 2) continue;
    const int f = edges.faces[e][0], h = edges.faces[e][1];
    int k = 0;
    while (edges.FE(f, k) != e) ++k;
    const int v0 = g.F(f, k), v1 = g.F(f, (k + 1) % 3), v2 = g.F(f, (k + 2) % 3);
    int j = 0;
    while (edges.FE(h, j) != e) ++j;
    if (g.F(h, j) != v1) continue;  // both triangles walk the edge the same way: misoriented
    const int v3 = g.F(h, (j + 2) % 3);
    // Rest edge length: the mean of its two pattern copies (equal unless the seam gathers).
    const double rest_length = 0.5 * ((g.P.row(g.FP(f, k)) - g.P.row(g.FP(f, (k + 1) % 3))).norm() +
                                      (g.P.row(g.FP(h, j)) - g.P.row(g.FP(h, (j + 1) % 3))).norm());
    m.hinges.push_back({{v0, v1, v2, v3}, hinge_stiffness(scene.material.bending, rest_length, m.rest[f].area, m.rest[h].area), 0.0});
  }

  m.stitch_stiffness = params.stitch_stiffness_factor * std::max(scene.material.stretch_warp, scene.material.stretch_weft);
  for (const Stitch& s : g.stitches) {
    const auto weights = [](const StitchPoint& p, double sign) {
      return std::array<double, 2>{sign * (p.v1 >= 0 ? 1.0 - p.t : 1.0), sign * (p.v1 >= 0 ? p.t : 0.0)};
    };
    const auto wa = weights(s.a, 1.0), wb = weights(s.b, -1.0);
    m.stitches.push_back({{s.a.v0, s.a.v1 >= 0 ? s.a.v1 : s.a.v0, s.b.v0, s.b.v1 >= 0 ? s.b.v1 : s.b.v0}, {wa[0], wa[1], wb[0], wb[1]}});
  }

  m.pins = pins_at(g.V, pinned);
  if (scene.physics.body_contact) {
    if (body == nullptr) throw ArgumentError("cloth_model: the scene asks for body contact but no body was given");
    m.body = std::move(body);
    m.contact_thickness = scene.body ? scene.body->thickness : 0.0;
    m.contact_stiffness = params.contact_stiffness;
  }
  if (scene.physics.self_contact) m.self_contact = self_contact_model(m, params, self_contact_region(scene, g.V));
  return m;
}

} // namespace foldsketch
