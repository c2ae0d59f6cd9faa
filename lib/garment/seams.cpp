#include "garment/seams.h"

#include <cstdint>
#include <unordered_map>

#include "mesh/boundary_loops.h"
#include "mesh/mesh_edges.h"

namespace foldsketch {

std::vector<BoundaryLoop> panel_boundaries(const Garment& g) {
  std::vector<BoundaryLoop> out;
  for (int p = 0; p < static_cast<int>(g.panels.size()); ++p)
    for (auto& loop : boundary_loops(panel_pattern_faces(g, p), static_cast<int>(g.P.rows())))
      out.push_back({p, std::move(loop)});
  return out;
}

namespace {
struct HalfEdge {
  int loop = -1, pos = -1;  // edge from loops[loop].vertices[pos] to the next vertex
  bool operator==(const HalfEdge&) const = default;
};

int wrap(int i, int n) { return ((i % n) + n) % n; }
} // namespace

std::vector<Seam> seams(const Garment& g, const std::vector<BoundaryLoop>& loops) {
  const VectorXi drape = pattern_to_drape(g);
  const auto vertex = [&](HalfEdge h, int offset) {
    const auto& v = loops[h.loop].vertices;
    return v[wrap(h.pos + offset, static_cast<int>(v.size()))];
  };

  std::unordered_map<std::uint64_t, std::vector<HalfEdge>> by_drape_edge;
  for (int l = 0; l < static_cast<int>(loops.size()); ++l)
    for (int i = 0; i < static_cast<int>(loops[l].vertices.size()); ++i) {
      const HalfEdge h{l, i};
      by_drape_edge[undirected_edge_key(drape(vertex(h, 0)), drape(vertex(h, 1)))].push_back(h);
    }
  // partner[l][i]: the other boundary half-edge on the same drape edge, if exactly one.
  std::vector<std::vector<HalfEdge>> partner(loops.size());
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    partner[l].resize(loops[l].vertices.size());
    for (int i = 0; i < static_cast<int>(loops[l].vertices.size()); ++i) {
      const HalfEdge h{l, i};
      const auto& list = by_drape_edge[undirected_edge_key(drape(vertex(h, 0)), drape(vertex(h, 1)))];
      if (list.size() == 2) partner[l][i] = list[0] == h ? list[1] : list[0];
    }
  }
  // Does half-edge h continue the run of its predecessor (same partner loop, partner stepping
  // by one in either direction and sharing the drape vertex)?
  const auto continues = [&](HalfEdge h) {
    const int n = static_cast<int>(loops[h.loop].vertices.size());
    const HalfEdge prev{h.loop, wrap(h.pos - 1, n)};
    const HalfEdge a = partner[h.loop][prev.pos], b = partner[h.loop][h.pos];
    if (a.loop < 0 || b.loop < 0 || a.loop != b.loop) return false;
    const int m = static_cast<int>(loops[a.loop].vertices.size());
    return b.pos == wrap(a.pos - 1, m) || b.pos == wrap(a.pos + 1, m);
  };
  // The partner vertex of pattern vertex v (an end of half-edge h) across the seam.
  const auto across = [&](HalfEdge h, int v) {
    const HalfEdge q = partner[h.loop][h.pos];
    return drape(vertex(q, 0)) == drape(v) ? vertex(q, 0) : vertex(q, 1);
  };

  std::vector<Seam> out;
  std::vector<std::vector<bool>> done(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) done[l].assign(loops[l].vertices.size(), false);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    const int n = static_cast<int>(loops[l].vertices.size());
    int start = 0;
    bool closed = true;
    for (int i = 0; i < n; ++i)
      if (!continues({l, i})) { start = i; closed = false; break; }
    for (int k = 0; k < n; ++k) {
      const int i = wrap(start + k, n);
      if (partner[l][i].loop < 0 || done[l][i]) continue;
      Seam seam;
      seam.closed = closed;
      seam.a.panel = loops[l].panel;
      seam.a.loop = l;
      seam.a.begin = i;
      seam.b.panel = loops[partner[l][i].loop].panel;
      seam.b.loop = partner[l][i].loop;
      HalfEdge h{l, i};
      seam.a.vertices.push_back(vertex(h, 0));
      seam.b.vertices.push_back(across(h, vertex(h, 0)));
      while (true) {
        done[l][h.pos] = true;
        const HalfEdge q = partner[l][h.pos];
        done[q.loop][q.pos] = true;
        const HalfEdge next{l, wrap(h.pos + 1, n)};
        if (next.pos == i || !continues(next) || done[l][next.pos]) {
          if (!closed) {
            seam.a.vertices.push_back(vertex(h, 1));
            seam.b.vertices.push_back(across(h, vertex(h, 1)));
          }
          break;
        }
        seam.a.vertices.push_back(vertex(h, 1));
        seam.b.vertices.push_back(across(h, vertex(h, 1)));
        h = next;
      }
      // side b starts where its first vertex sits in its loop
      const auto& bl = loops[seam.b.loop].vertices;
      for (int j = 0; j < static_cast<int>(bl.size()); ++j)
        if (bl[j] == seam.b.vertices.front()) { seam.b.begin = j; break; }
      out.push_back(std::move(seam));
    }
  }
  return out;
}

double pattern_length(const MatrixX2d& P, const std::vector<int>& vertices, bool closed) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < vertices.size(); ++i) length += (P.row(vertices[i + 1]) - P.row(vertices[i])).norm();
  if (closed && vertices.size() > 1) length += (P.row(vertices.front()) - P.row(vertices.back())).norm();
  return length;
}

double drape_length(const Garment& g, const std::vector<int>& vertices, bool closed) {
  const VectorXi drape = pattern_to_drape(g);
  double length = 0.0;
  const auto d = [&](int a, int b) { return (g.V.row(drape(a)) - g.V.row(drape(b))).norm(); };
  for (size_t i = 0; i + 1 < vertices.size(); ++i) length += d(vertices[i], vertices[i + 1]);
  if (closed && vertices.size() > 1) length += d(vertices.back(), vertices.front());
  return length;
}

} // namespace foldsketch
