#include "samples/grid_garment.h"

#include "core/error.h"
#include "mesh/isotropic_mesh.h"
#include "mesh/weld_vertices.h"

#include <algorithm>

namespace foldsketch {

namespace {

// One panel as a triangle mesh: pattern points, triangles (counter-clockwise) and drape points.
struct PanelMesh {
  std::string name;
  MatrixX2d pattern;
  MatrixX3i triangles;
  MatrixX3d drape;
};

void check_sizes(const GridPanel& p) {
  if (p.columns < 2 || p.rows < 2 || p.pattern.rows() != p.columns * p.rows || p.drape.rows() != p.pattern.rows())
    throw ArgumentError("grid panel '" + p.name + "' has inconsistent sizes");
}

// The grid's cells split in two, diagonals alternating like a chequerboard.
MatrixX3i grid_triangles(const GridPanel& p) {
  MatrixX3i F(2 * (p.columns - 1) * (p.rows - 1), 3);
  int face = 0;
  const auto id = [&](int i, int j) { return j * p.columns + i; };
  for (int j = 0; j + 1 < p.rows; ++j)
    for (int i = 0; i + 1 < p.columns; ++i) {
      if ((i + j) % 2 == 0) {
        F.row(face++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
        F.row(face++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
      } else {
        F.row(face++) << id(i, j), id(i + 1, j), id(i, j + 1);
        F.row(face++) << id(i + 1, j), id(i + 1, j + 1), id(i, j + 1);
      }
    }
  return F;
}

// All panels into one garment, drape points of different panels welded when closer than
// weld_tolerance.
Garment assemble(const std::vector<PanelMesh>& panels, double weld_tolerance) {
  int nodes = 0, faces = 0;
  for (const PanelMesh& p : panels) {
    nodes += static_cast<int>(p.pattern.rows());
    faces += static_cast<int>(p.triangles.rows());
  }
  Garment g;
  g.P.resize(nodes, 2);
  MatrixX3d unwelded(nodes, 3);
  g.FP.resize(faces, 3);
  g.face_panel.resize(faces);
  int node0 = 0, face0 = 0;
  for (int k = 0; k < static_cast<int>(panels.size()); ++k) {
    const PanelMesh& p = panels[k];
    const int n = static_cast<int>(p.pattern.rows()), m = static_cast<int>(p.triangles.rows());
    g.panels.push_back({p.name});
    g.P.middleRows(node0, n) = p.pattern;
    unwelded.middleRows(node0, n) = p.drape;
    g.FP.middleRows(face0, m) = p.triangles.array() + node0;
    g.face_panel.segment(face0, m).setConstant(k);
    node0 += n;
    face0 += m;
  }
  const VectorXi weld = weld_vertices(unwelded, weld_tolerance);
  g.V = welded_positions(unwelded, weld);
  g.F.resize(g.FP.rows(), 3);
  for (int f = 0; f < g.FP.rows(); ++f)
    for (int c = 0; c < 3; ++c) g.F(f, c) = weld(g.FP(f, c));
  return g;
}

// Boundary nodes of a grid panel, counter-clockwise from node (0, 0).
std::vector<int> grid_outline(const GridPanel& p) {
  std::vector<int> out;
  for (int i = 0; i < p.columns; ++i) out.push_back(i);
  for (int j = 1; j < p.rows; ++j) out.push_back(j * p.columns + p.columns - 1);
  for (int i = p.columns - 2; i >= 0; --i) out.push_back((p.rows - 1) * p.columns + i);
  for (int j = p.rows - 2; j >= 1; --j) out.push_back(j * p.columns);
  return out;
}

// Drape position of pattern point q by the grid's piecewise-linear map: barycentric
// interpolation in the grid triangle containing q (the nearest one if q is outside by roundoff).
Vector3d grid_drape_at(const GridPanel& p, const MatrixX3i& F, const Vector2d& q) {
  double best = -1e300;
  Vector3d at = Vector3d::Zero();
  for (int f = 0; f < F.rows(); ++f) {
    const Vector2d a = p.pattern.row(F(f, 0)), b = p.pattern.row(F(f, 1)), c = p.pattern.row(F(f, 2));
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    const double wa = ((b - q).x() * (c - q).y() - (b - q).y() * (c - q).x()) / area;
    const double wb = ((c - q).x() * (a - q).y() - (c - q).y() * (a - q).x()) / area;
    const double wc = 1.0 - wa - wb;
    const double inside = std::min({wa, wb, wc});
    if (inside > best) {
      best = inside;
      at = wa * p.drape.row(F(f, 0)).transpose() + wb * p.drape.row(F(f, 1)).transpose() + wc * p.drape.row(F(f, 2)).transpose();
      if (inside >= 0.0) break;
    }
  }
  return at;
}

} // namespace

Garment grid_garment(const std::vector<GridPanel>& panels, double weld_tolerance) {
  std::vector<PanelMesh> meshes;
  for (const GridPanel& p : panels) {
    check_sizes(p);
    meshes.push_back({p.name, p.pattern, grid_triangles(p), p.drape});
  }
  return assemble(meshes, weld_tolerance);
}

Garment isotropic_garment(const std::vector<GridPanel>& panels, double spacing, double weld_tolerance) {
  std::vector<PanelMesh> meshes;
  for (const GridPanel& p : panels) {
    check_sizes(p);
    const std::vector<int> outline = grid_outline(p);
    MatrixX2d O(static_cast<long>(outline.size()), 2);
    for (size_t k = 0; k < outline.size(); ++k) O.row(static_cast<long>(k)) = p.pattern.row(outline[k]);
    const PlanarMesh planar = isotropic_mesh(O, spacing);
    const MatrixX3i F = grid_triangles(p);
    PanelMesh mesh{p.name, planar.P, planar.F, MatrixX3d(planar.P.rows(), 3)};
    for (int v = 0; v < planar.P.rows(); ++v)
      mesh.drape.row(v) = v < static_cast<int>(outline.size()) ? Vector3d(p.drape.row(outline[static_cast<size_t>(v)]))
                                                               : grid_drape_at(p, F, planar.P.row(v));
    meshes.push_back(std::move(mesh));
  }
  return assemble(meshes, weld_tolerance);
}

GridPanel flat_panel(const std::string& name, int nu, int nv, double width, double height, const Vector3d& origin,
                     const Vector3d& across, const Vector3d& up) {
  GridPanel p{name, nu + 1, nv + 1, MatrixX2d((nu + 1) * (nv + 1), 2), MatrixX3d((nu + 1) * (nv + 1), 3)};
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double u = width * i / nu, v = height * j / nv;
      p.pattern.row(j * (nu + 1) + i) << u, v;
      p.drape.row(j * (nu + 1) + i) = (origin + u * across + v * up).transpose();
    }
  return p;
}

void lay_out_patterns(std::vector<GridPanel>& panels, double gap) {
  double x = 0.0;
  for (GridPanel& p : panels) {
    const Vector2d lo = p.pattern.colwise().minCoeff(), hi = p.pattern.colwise().maxCoeff();
    p.pattern.rowwise() += Vector2d(x - lo.x(), -lo.y()).transpose();
    x += hi.x() - lo.x() + gap;
  }
}

} // namespace foldsketch
