#include "samples/grid_garment.h"

#include "core/error.h"
#include "mesh/weld_vertices.h"

namespace foldsketch {

Garment grid_garment(const std::vector<GridPanel>& panels, double weld_tolerance) {
  int nodes = 0, cells = 0;
  for (const GridPanel& p : panels) {
    if (p.columns < 2 || p.rows < 2 || p.pattern.rows() != p.columns * p.rows || p.drape.rows() != p.pattern.rows())
      throw ArgumentError("grid_garment: panel '" + p.name + "' has inconsistent sizes");
    nodes += p.columns * p.rows;
    cells += (p.columns - 1) * (p.rows - 1);
  }
  Garment g;
  g.P.resize(nodes, 2);
  MatrixX3d unwelded(nodes, 3);
  g.FP.resize(2 * cells, 3);
  g.face_panel.resize(2 * cells);
  int node0 = 0, face = 0;
  for (int k = 0; k < static_cast<int>(panels.size()); ++k) {
    const GridPanel& p = panels[k];
    g.panels.push_back({p.name});
    g.P.middleRows(node0, p.columns * p.rows) = p.pattern;
    unwelded.middleRows(node0, p.columns * p.rows) = p.drape;
    const auto id = [&](int i, int j) { return node0 + j * p.columns + i; };
    for (int j = 0; j + 1 < p.rows; ++j)
      for (int i = 0; i + 1 < p.columns; ++i) {
        if ((i + j) % 2 == 0) {
          g.FP.row(face++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
          g.FP.row(face++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
        } else {
          g.FP.row(face++) << id(i, j), id(i + 1, j), id(i, j + 1);
          g.FP.row(face++) << id(i + 1, j), id(i + 1, j + 1), id(i, j + 1);
        }
        g.face_panel(face - 2) = g.face_panel(face - 1) = k;
      }
    node0 += p.columns * p.rows;
  }
  const VectorXi weld = weld_vertices(unwelded, weld_tolerance);
  g.V = welded_positions(unwelded, weld);
  g.F.resize(g.FP.rows(), 3);
  for (int f = 0; f < g.FP.rows(); ++f)
    for (int c = 0; c < 3; ++c) g.F(f, c) = weld(g.FP(f, c));
  return g;
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
