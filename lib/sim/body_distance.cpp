#include "sim/body_distance.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <Eigen/Geometry>

#include "core/error.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {
namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// An edge is concave when a corner of the face across lies on the outer side of this face's
// plane by more than this fraction of the edge length (flat edges are not concave: there the
// closest point moves continuously).
constexpr double kConcaveTolerance = 1e-9;
} // namespace

struct BodyDistance::Tree {
  std::vector<Triangle> triangles;
  foldsketch::Tree tree;
};

BodyDistance::BodyDistance(const TriangleMesh& body) : tree_(std::make_unique<Tree>()) {
  if (body.F.rows() == 0) throw ArgumentError("BodyDistance: the body has no triangles");
  normals_.resize(body.F.rows(), 3);
  for (int f = 0; f < body.F.rows(); ++f) {
    const Vector3d a = body.V.row(body.F(f, 0)), b = body.V.row(body.F(f, 1)), c = body.V.row(body.F(f, 2));
    tree_->triangles.emplace_back(Kernel::Point_3(a.x(), a.y(), a.z()), Kernel::Point_3(b.x(), b.y(), b.z()),
                                  Kernel::Point_3(c.x(), c.y(), c.z()));
    const Vector3d n = (b - a).cross(c - a);
    normals_.row(f) = n.norm() > 0 ? n.normalized() : Vector3d::Zero();
  }
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.accelerate_distance_queries();

  // Edges, and which are concave: the face across lies on the outside of this face's plane.
  vertices_ = body.V;
  faces_ = body.F;
  face_edges_.resize(body.F.rows(), 3);
  std::map<std::array<int, 2>, int> edge_index;
  std::vector<std::vector<int>> edge_faces;
  for (int f = 0; f < body.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> e{body.F(f, k), body.F(f, (k + 1) % 3)};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      const auto [it, added] = edge_index.emplace(e, static_cast<int>(edges_.size()));
      if (added) edges_.push_back(e), edge_faces.emplace_back();
      face_edges_(f, k) = it->second;
      edge_faces[static_cast<size_t>(it->second)].push_back(f);
    }
  face_near_concave_.assign(static_cast<size_t>(body.F.rows()), 0);
  for (size_t e = 0; e < edges_.size(); ++e) {
    const std::vector<int>& fs = edge_faces[e];
    if (fs.size() != 2) continue;
    const Vector3d a = body.V.row(edges_[e][0]), b = body.V.row(edges_[e][1]);
    const double scale = (b - a).norm();
    bool concave = false;
    for (int side = 0; side < 2; ++side) {
      const int f = fs[static_cast<size_t>(side)], g = fs[static_cast<size_t>(1 - side)];
      for (int k = 0; k < 3; ++k) {
        const int v = body.F(g, k);
        if (v == edges_[e][0] || v == edges_[e][1]) continue;
        concave = concave || normals_.row(f).dot(body.V.row(v) - body.V.row(edges_[e][0])) > kConcaveTolerance * scale;
      }
    }
    if (concave) face_near_concave_[static_cast<size_t>(fs[0])] = face_near_concave_[static_cast<size_t>(fs[1])] = 1;
  }
}

BodyDistance::~BodyDistance() = default;
BodyDistance::BodyDistance(BodyDistance&&) noexcept = default;
BodyDistance& BodyDistance::operator=(BodyDistance&&) noexcept = default;

BodyPoint BodyDistance::at(const Vector3d& p) const {
  const auto [point, primitive] = tree_->tree.closest_point_and_primitive(Kernel::Point_3(p.x(), p.y(), p.z()));
  const auto f = static_cast<int>(primitive - tree_->triangles.cbegin());
  BodyPoint out;
  out.closest = {point.x(), point.y(), point.z()};
  out.face = f;
  out.normal = normals_.row(f);
  const Vector3d offset = p - out.closest;
  // The closest triangle's side decides the sign. Off its interior (closest point on an edge or
  // corner) the offset direction is the better normal for the penalty force.
  const double unsigned_distance = offset.norm();
  out.distance = offset.dot(out.normal) >= 0 ? unsigned_distance : -unsigned_distance;
  if (unsigned_distance > 1e-12 * (1.0 + p.norm())) {
    const Vector3d direction = offset / unsigned_distance;
    out.normal = out.distance >= 0 ? direction : Vector3d(-direction);
  }
  return out;
}

BodyFeaturePoint BodyDistance::closest_on_face(const Vector3d& p, int face) const {
  const Triangle& t = tree_->triangles[static_cast<size_t>(face)];
  const Vector3d a(t[0].x(), t[0].y(), t[0].z()), b(t[1].x(), t[1].y(), t[1].z()), c(t[2].x(), t[2].y(), t[2].z());
  const TriangleClosestPoint cp = closest_point_on_triangle(p, a, b, c);
  BodyFeaturePoint out;
  out.closest = cp.weights(0) * a + cp.weights(1) * b + cp.weights(2) * c;
  // closest_point_on_triangle's feature: 0 the face, 1-3 the edges ab, bc, ca, 4-6 the corners.
  out.on_face = cp.feature == 0;
  if (cp.feature >= 1 && cp.feature <= 3) {
    const Vector3d& from = cp.feature == 1 ? a : cp.feature == 2 ? b : c;
    const Vector3d& to = cp.feature == 1 ? b : cp.feature == 2 ? c : a;
    out.edge = (to - from).normalized();
  }
  return out;
}

std::vector<BodyFeaturePoint> BodyDistance::contact_features(const Vector3d& p, double radius) const {
  const CGAL::Bbox_3 box(p.x() - radius, p.y() - radius, p.z() - radius, p.x() + radius, p.y() + radius, p.z() + radius);
  std::vector<Iterator> candidates;
  tree_->tree.all_intersected_primitives(box, std::back_inserter(candidates));
  // Most of a body is far from any concave edge: settle that before computing distances.
  if (std::none_of(candidates.begin(), candidates.end(), [&](const Iterator& id) {
        return face_near_concave_[static_cast<size_t>(id - tree_->triangles.cbegin())] != 0;
      }))
    return {};
  std::vector<BodyFeaturePoint> out;
  std::vector<int> near_faces;
  bool concave = false;
  for (const Iterator& id : candidates) {
    const int f = static_cast<int>(id - tree_->triangles.cbegin());
    const BodyFeaturePoint term = closest_on_face(p, f);
    if (!((p - term.closest).norm() < radius)) continue;
    concave = concave || face_near_concave_[static_cast<size_t>(f)];
    near_faces.push_back(f);
    out.push_back(term);
  }
  if (!concave) return {};
  // Edges and corners of the faces within reach (every edge or corner within reach is one).
  std::vector<int> edges, corners;
  for (int f : near_faces)
    for (int k = 0; k < 3; ++k) edges.push_back(face_edges_(f, k)), corners.push_back(faces_(f, k));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (int e : edges) {
    const Vector3d a = vertices_.row(edges_[static_cast<size_t>(e)][0]), b = vertices_.row(edges_[static_cast<size_t>(e)][1]);
    const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    BodyFeaturePoint term;
    term.closest = a + s * (b - a);
    if (!((p - term.closest).norm() < radius)) continue;
    term.weight = -1;
    if (s > 0.0 && s < 1.0) term.edge = (b - a).normalized();
    out.push_back(term);
  }
  for (int v : corners) {
    BodyFeaturePoint term;
    term.closest = vertices_.row(v);
    if (!((p - term.closest).norm() < radius)) continue;
    out.push_back(term);
  }
  return out;
}

} // namespace foldsketch
