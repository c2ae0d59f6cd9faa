#include "garment/drape_transfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace foldsketch {
namespace {

// Barycentric coordinates of the point of triangle (a, b, c) nearest to q, and its squared
// distance to q.
struct Nearest {
  Eigen::Vector3d weights;
  double distance2 = std::numeric_limits<double>::infinity();
};

Nearest nearest_on_segment(const Vector2d& q, const Vector2d& a, const Vector2d& b, int ia, int ib) {
  const Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  Nearest n;
  n.weights.setZero();
  n.weights(ia) = 1.0 - t;
  n.weights(ib) = t;
  n.distance2 = (a + t * ab - q).squaredNorm();
  return n;
}

Nearest nearest_on_triangle(const Vector2d& q, const Vector2d& a, const Vector2d& b, const Vector2d& c) {
  const double area2 = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  if (std::abs(area2) > 0.0) {
    const auto cross = [](const Vector2d& u, const Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
    const Eigen::Vector3d w(cross(b - q, c - q) / area2, cross(c - q, a - q) / area2, cross(a - q, b - q) / area2);
    if (w.minCoeff() >= 0.0) return {w, 0.0};
  }
  Nearest best = nearest_on_segment(q, a, b, 0, 1);
  for (const Nearest& n : {nearest_on_segment(q, b, c, 1, 2), nearest_on_segment(q, c, a, 2, 0)})
    if (n.distance2 < best.distance2) best = n;
  return best;
}

// The source triangles of one panel in a uniform grid of buckets over their bounding box, for
// point location.
class PanelGrid {
 public:
  PanelGrid(const Garment& g, const std::vector<int>& faces) : g_(g), faces_(faces) {
    lo_ = Vector2d::Constant(std::numeric_limits<double>::infinity());
    Vector2d hi = -lo_;
    for (int f : faces)
      for (int k = 0; k < 3; ++k) {
        lo_ = lo_.cwiseMin(g.P.row(g.FP(f, k)).transpose());
        hi = hi.cwiseMax(g.P.row(g.FP(f, k)).transpose());
      }
    // About two triangles per bucket.
    const Vector2d extent = (hi - lo_).cwiseMax(1e-12);
    const double cell = std::sqrt(extent.prod() / std::max<size_t>(1, faces.size()) * 2.0);
    nx_ = std::max(1, static_cast<int>(std::ceil(extent.x() / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil(extent.y() / cell)));
    cell_ = Vector2d(extent.x() / nx_, extent.y() / ny_);
    buckets_.resize(static_cast<size_t>(nx_) * ny_);
    for (size_t i = 0; i < faces.size(); ++i) {
      Vector2d a = g.P.row(g.FP(faces[i], 0)).transpose(), b = a;
      for (int k = 1; k < 3; ++k) {
        a = a.cwiseMin(g.P.row(g.FP(faces[i], k)).transpose());
        b = b.cwiseMax(g.P.row(g.FP(faces[i], k)).transpose());
      }
      const auto [x0, y0] = cell_of(a);
      const auto [x1, y1] = cell_of(b);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) buckets_[static_cast<size_t>(y) * nx_ + x].push_back(static_cast<int>(i));
    }
  }

  // The source face nearest to q and the barycentric weights of the nearest point on it.
  std::pair<int, Eigen::Vector3d> locate(const Vector2d& q) const {
    Nearest best;
    int best_face = -1;
    const auto [cx, cy] = cell_of(q);
    // Rings of buckets around q's bucket, until a ring cannot hold anything nearer.
    for (int ring = 0; ring <= std::max(nx_, ny_); ++ring) {
      for (int y = cy - ring; y <= cy + ring; ++y)
        for (int x = cx - ring; x <= cx + ring; ++x) {
          if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring || x < 0 || y < 0 || x >= nx_ || y >= ny_) continue;
          for (int i : buckets_[static_cast<size_t>(y) * nx_ + x]) {
            const int f = faces_[static_cast<size_t>(i)];
            const Nearest n = nearest_on_triangle(q, g_.P.row(g_.FP(f, 0)), g_.P.row(g_.FP(f, 1)), g_.P.row(g_.FP(f, 2)));
            if (n.distance2 < best.distance2) best = n, best_face = f;
          }
        }
      // Every bucket outside this ring is at least `ring` cells from q's bucket.
      const double reach = ring * cell_.minCoeff();
      if (best_face >= 0 && best.distance2 <= reach * reach) break;
    }
    return {best_face, best.weights};
  }

 private:
  std::pair<int, int> cell_of(const Vector2d& q) const {
    const int x = std::clamp(static_cast<int>(std::floor((q.x() - lo_.x()) / cell_.x())), 0, nx_ - 1);
    const int y = std::clamp(static_cast<int>(std::floor((q.y() - lo_.y()) / cell_.y())), 0, ny_ - 1);
    return {x, y};
  }

  const Garment& g_;
  const std::vector<int>& faces_;
  Vector2d lo_, cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> buckets_;
};

} // namespace

MatrixX3d transfer_drape(const Garment& from, const MatrixX3d& from_V, const Garment& to) {
  if (from_V.rows() != from.V.rows()) throw ArgumentError("transfer_drape: the drape has the wrong number of vertices");
  if (from.panels != to.panels) throw ArgumentError("transfer_drape: the two garments have different panels");
  MatrixX3d V = MatrixX3d::Zero(to.V.rows(), 3);
  VectorXd count = VectorXd::Zero(to.V.rows());
  std::vector<char> done(static_cast<size_t>(to.P.rows()), 0);
  for (int p = 0; p < static_cast<int>(from.panels.size()); ++p) {
    const std::vector<int> source = panel_faces(from, p);
    const std::vector<int> target = panel_faces(to, p);
    if (target.empty()) continue;
    if (source.empty())
      throw ArgumentError("transfer_drape: panel '" + from.panels[static_cast<size_t>(p)].name + "' has no triangles in the source");
    const PanelGrid grid(from, source);
    for (int f : target)
      for (int k = 0; k < 3; ++k) {
        const int q = to.FP(f, k);
        if (done[static_cast<size_t>(q)]) continue;
        done[static_cast<size_t>(q)] = 1;
        const auto [face, w] = grid.locate(to.P.row(q).transpose());
        const Vector3d x = w(0) * from_V.row(from.F(face, 0)) + w(1) * from_V.row(from.F(face, 1)) + w(2) * from_V.row(from.F(face, 2));
        V.row(to.F(f, k)) += x.transpose();
        count(to.F(f, k)) += 1.0;
      }
  }
  for (int v = 0; v < V.rows(); ++v)
    V.row(v) = count(v) > 0.0 ? Eigen::RowVector3d(V.row(v) / count(v)) : Eigen::RowVector3d(to.V.row(v));
  return V;
}

} // namespace foldsketch
