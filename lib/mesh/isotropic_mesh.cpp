#include "mesh/isotropic_mesh.h"

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "core/error.h"

namespace foldsketch {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Point = Kernel::Point_2;

double segment_distance(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}
} // namespace

PlanarMesh isotropic_mesh(const MatrixX2d& outline, double spacing, const IsotropicMeshParams& params,
                          const std::vector<MatrixX2d>& holes) {
  const int n = static_cast<int>(outline.rows());
  if (n < 3 || !(spacing > 0.0)) throw ArgumentError("isotropic_mesh: need an outline of 3+ points and a positive spacing");
  std::vector<Point> polygon;
  for (int i = 0; i < n; ++i) polygon.emplace_back(outline(i, 0), outline(i, 1));
  if (!CGAL::is_simple_2(polygon.begin(), polygon.end(), Kernel())) throw ArgumentError("isotropic_mesh: the outline crosses itself");
  if (CGAL::orientation_2(polygon.begin(), polygon.end(), Kernel()) != CGAL::COUNTERCLOCKWISE)
    throw ArgumentError("isotropic_mesh: the outline must be counter-clockwise");

  std::vector<std::vector<Point>> hole_polygons;
  for (const MatrixX2d& h : holes) {
    std::vector<Point> hole;
    for (int i = 0; i < h.rows(); ++i) hole.emplace_back(h(i, 0), h(i, 1));
    if (hole.size() < 3 || !CGAL::is_simple_2(hole.begin(), hole.end(), Kernel()))
      throw ArgumentError("isotropic_mesh: a hole needs 3+ points and must not cross itself");
    hole_polygons.push_back(hole);
  }

  // Outline points, then each hole's; the constraints are the closed loops between them.
  std::vector<Vector2d> points;
  std::vector<std::pair<int, int>> constraints;
  const auto add_loop = [&](const MatrixX2d& loop) {
    const int first = static_cast<int>(points.size()), count = static_cast<int>(loop.rows());
    for (int i = 0; i < count; ++i) points.emplace_back(loop.row(i).transpose());
    for (int i = 0; i < count; ++i) constraints.emplace_back(first + i, first + (i + 1) % count);
  };
  add_loop(outline);
  for (const MatrixX2d& h : holes) add_loop(h);
  // Hexagonal lattice over the bounding box, jittered, kept inside and clear of the outline.
  const Vector2d lo = outline.colwise().minCoeff(), hi = outline.colwise().maxCoeff();
  std::mt19937 rng(params.seed);
  std::uniform_real_distribution<double> jitter(-params.jitter * spacing, params.jitter * spacing);
  const double row_height = spacing * std::sqrt(3.0) / 2.0;
  for (int j = 0; lo.y() + j * row_height <= hi.y(); ++j)
    for (int i = 0; lo.x() + (i + 0.5 * (j % 2)) * spacing <= hi.x(); ++i) {
      const Vector2d base(lo.x() + (i + 0.5 * (j % 2)) * spacing, lo.y() + j * row_height);
      const Vector2d p = base + Vector2d(jitter(rng), jitter(rng));
      if (CGAL::bounded_side_2(polygon.begin(), polygon.end(), Point(p.x(), p.y()), Kernel()) != CGAL::ON_BOUNDED_SIDE) continue;
      bool clear = true;
      for (const auto& hole : hole_polygons)
        clear = clear && CGAL::bounded_side_2(hole.begin(), hole.end(), Point(p.x(), p.y()), Kernel()) == CGAL::ON_UNBOUNDED_SIDE;
      for (const auto& [a, b] : constraints) {
        if (!clear) break;
        clear = segment_distance(p, points[a], points[b]) >= params.boundary_clearance * spacing;
      }
      if (clear) points.push_back(p);
    }

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (size_t i = 0; i < points.size(); ++i) {
    handles.push_back(cdt.insert(Point(points[i].x(), points[i].y())));
    handles.back()->info() = static_cast<int>(i);
  }
  for (const auto& [a, b] : constraints) cdt.insert_constraint(handles[a], handles[b]);
  if (static_cast<size_t>(cdt.number_of_vertices()) != points.size())
    throw ArgumentError("isotropic_mesh: outline points coincide, or constraints crossed and added points");

  // Inside faces by flood fill from the infinite face, counting crossings of the outline's
  // constraints: exact, where testing a face's centroid is not (the centroid of a sliver along
  // an outline that is straight only up to roundoff can land on either side).
  std::map<Cdt::Face_handle, int> depth;
  std::vector<Cdt::Face_handle> frontier{cdt.infinite_face()};
  depth[cdt.infinite_face()] = 0;
  for (size_t k = 0; k < frontier.size(); ++k) {
    const Cdt::Face_handle f = frontier[k];
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle g = f->neighbor(i);
      if (depth.count(g)) continue;
      depth[g] = depth[f] + (cdt.is_constrained({f, i}) ? 1 : 0);
      frontier.push_back(g);
    }
  }
  std::vector<std::array<int, 3>> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (depth[f] % 2 == 0) continue;
    faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});  // CGAL faces are CCW
  }
  PlanarMesh mesh;
  mesh.P.resize(static_cast<long>(points.size()), 2);
  for (size_t i = 0; i < points.size(); ++i) mesh.P.row(static_cast<long>(i)) = points[i].transpose();
  mesh.F.resize(static_cast<long>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) mesh.F.row(static_cast<long>(f)) << faces[f][0], faces[f][1], faces[f][2];
  return mesh;
}

} // namespace foldsketch
