#include "garment/drape_transfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/error.h"
#include "mesh/triangle_geometry.h"

namespace foldsketch {
namespace {

// Barycentric weights of the point of a pattern triangle nearest to q, and its squared distance.
struct Nearest {
  Eigen::Vector3d weights;
  double distance2 = std::numeric_limits<double>::infinity();
};

Nearest nearest_on_triangle(const Vector2d& q, const Vector2d& a, const Vector2d& b, const Vector2d& c) {
  const auto lifted = [](const Vector2d& p) { return Vector3d(p.x(), p.y(), 0.0); };
  const Vector3d w = closest_point_on_triangle(lifted(q), lifted(a), lifted(b), lifted(c)).weights;
  return {w, (w(0) * a + w(1) * b + w(2) * c - q).squaredNorm()};
}

// The source triangles of one panel in a uniform grid of buckets over their bounding box, for
// point location.
class PanelGrid {
 public:
  PanelGrid(const Garment& g, const std::vector<int>& faces) : g_(g), faces_(faces) {
    std::vector<Eigen::AlignedBox2d> boxes(faces.size());
    Eigen::AlignedBox2d panel;
    for (size_t i = 0; i < faces.size(); ++i) {
      for (int k = 0; k < 3; ++k) boxes[i].extend(g.P.row(g.FP(faces[i], k)).transpose());
      panel.extend(boxes[i]);
    }
    lo_ = panel.min();
    // About two triangles per bucket.
    const Vector2d extent = panel.sizes().cwiseMax(1e-12);
    const double cell = std::sqrt(extent.prod() / std::max<size_t>(1, faces.size()) * 2.0);
    nx_ = std::max(1, static_cast<int>(std::ceil(extent.x() / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil(extent.y() / cell)));
    cell_ = Vector2d(extent.x() / nx_, extent.y() / ny_);
    buckets_.resize(static_cast<size_t>(nx_) * ny_);
    for (size_t i = 0; i < faces.size(); ++i) {
      const auto [x0, y0] = cell_of(boxes[i].min());
      const auto [x1, y1] = cell_of(boxes[i].max());
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
