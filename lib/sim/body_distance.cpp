#include "sim/body_distance.h"

#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <Eigen/Geometry>

#include "core/error.h"

namespace foldsketch {
namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
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
}

BodyDistance::~BodyDistance() = default;
BodyDistance::BodyDistance(BodyDistance&&) noexcept = default;
BodyDistance& BodyDistance::operator=(BodyDistance&&) noexcept = default;

BodyPoint BodyDistance::at(const Vector3d& p) const {
  const auto [point, primitive] = tree_->tree.closest_point_and_primitive(Kernel::Point_3(p.x(), p.y(), p.z()));
  const auto f = static_cast<int>(primitive - tree_->triangles.cbegin());
  BodyPoint out;
  out.closest = {point.x(), point.y(), point.z()};
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

} // namespace foldsketch
