#include "sim/self_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>

namespace foldsketch {
namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

// A value with its gradient and Hessian over the 12 coordinates of (p, a, b, c), carried
// through each operation (second-order forward differentiation). The distance formulas below
// are short, so this costs a few thousand flops per pair and cannot disagree with them.
struct Hyper {
  double v = 0;
  Vec12 g = Vec12::Zero();
  Mat12 H = Mat12::Zero();
};
using Hyper3 = std::array<Hyper, 3>;

// Edge-edge mollifier (Li et al. 2020, Incremental Potential Contact, section 4.3): the pair's
// energy fades smoothly to zero as the edges turn parallel, below |u x v|^2 = kMollifier |u|^2
// |v|^2, where their closest points are ill-defined.
constexpr double kMollifier = 1e-3;

Hyper operator+(const Hyper& a, const Hyper& b) { return {a.v + b.v, a.g + b.g, a.H + b.H}; }
Hyper operator-(const Hyper& a, const Hyper& b) { return {a.v - b.v, a.g - b.g, a.H - b.H}; }
Hyper operator*(const Hyper& a, const Hyper& b) {
  const Mat12 outer = a.g * b.g.transpose();
  return {a.v * b.v, a.v * b.g + b.v * a.g, a.v * b.H + b.v * a.H + outer + outer.transpose()};
}
// f(a) from f(a.v), f'(a.v), f''(a.v).
Hyper chain(const Hyper& a, double f, double f1, double f2) { return {f, f1 * a.g, f1 * a.H + f2 * a.g * a.g.transpose()}; }
Hyper reciprocal(const Hyper& a) { return chain(a, 1.0 / a.v, -1.0 / (a.v * a.v), 2.0 / (a.v * a.v * a.v)); }
Hyper constant(double value) { return {value, Vec12::Zero(), Mat12::Zero()}; }
Hyper root(const Hyper& a) {
  const double r = std::sqrt(a.v);
  return chain(a, r, 0.5 / r, -0.25 / (r * a.v));
}

Hyper3 corner(const Eigen::Matrix<double, 12, 1>& q, int k) {
  Hyper3 out;
  for (int c = 0; c < 3; ++c) {
    out[c].v = q(3 * k + c);
    out[c].g(3 * k + c) = 1.0;
  }
  return out;
}
Hyper3 minus(const Hyper3& a, const Hyper3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Hyper dot(const Hyper3& a, const Hyper3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Hyper3 cross(const Hyper3& a, const Hyper3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Squared distance from point (corner i) to the line through corners j, k.
Hyper point_line_squared(const Vec12& q, int i, int j, int k) {
  const Hyper3 xj = corner(q, j);
  const Hyper3 e = minus(corner(q, k), xj);
  const Hyper3 r = cross(minus(corner(q, i), xj), e);
  return dot(r, r) * reciprocal(dot(e, e));
}

// Squared distance from p (corner 0) to the given feature of triangle (corners 1, 2, 3):
// each formula is smooth inside its feature's region, and they agree to first order where
// regions meet.
Hyper squared_distance(const Vec12& q, int feature) {
  const Hyper3 p = corner(q, 0);
  if (feature == 0) {  // face: ((p - a).n)^2 / |n|^2
    const Hyper3 a = corner(q, 1);
    const Hyper3 n = cross(minus(corner(q, 2), a), minus(corner(q, 3), a));
    const Hyper h = dot(minus(p, a), n);
    return h * h * reciprocal(dot(n, n));
  }
  if (feature <= 3) return point_line_squared(q, 0, feature, feature % 3 + 1);  // edge
  const Hyper3 r = minus(p, corner(q, feature - 3));                            // corner
  return dot(r, r);
}

// Uniform grid of boxes, for the broad phase: items are listed in every cell their box
// touches, queries read the cells of a point or a box.
class CellGrid {
public:
  explicit CellGrid(double cell) : cell_(cell) {}
  void insert(const Eigen::AlignedBox3d& box, int item) {
    if (!box.min().allFinite() || !box.max().allFinite()) return;  // a NaN state: its energy is NaN anyway
    const Eigen::Vector3i lo = index(box.min()), hi = index(box.max());
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) entries_.push_back({key({i, j, k}), item});
  }
  void finish() { std::sort(entries_.begin(), entries_.end()); }
  // Calls f(item) for every item listed in a cell touching `box` (an item may come repeatedly).
  template <typename F>
  void query(const Eigen::AlignedBox3d& box, F f) const {
    if (!box.min().allFinite() || !box.max().allFinite()) return;
    const Eigen::Vector3i lo = index(box.min()), hi = index(box.max());
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) {
          const uint64_t cell = key({i, j, k});
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<uint64_t, int>{cell, -1});
          for (; it != entries_.end() && it->first == cell; ++it) f(it->second);
        }
  }

private:
  Eigen::Vector3i index(const Vector3d& p) const { return (p / cell_).array().floor().cast<int>(); }
  // 21 bits per axis: +-1e6 cells, 10 km at 1 cm cells.
  static uint64_t key(const Eigen::Vector3i& c) {
    constexpr int64_t kOffset = int64_t{1} << 20;
    const auto part = [&](int v) { return static_cast<uint64_t>(std::clamp<int64_t>(v + kOffset, 0, 2 * kOffset - 1)); };
    return part(c.x()) << 42 | part(c.y()) << 21 | part(c.z());
  }
  double cell_;
  std::vector<std::pair<uint64_t, int>> entries_;
};

Eigen::AlignedBox3d box_of(const MatrixX3d& x, const int* vs, int count, double margin) {
  Eigen::AlignedBox3d box;
  for (int i = 0; i < count; ++i) box.extend(Vector3d(x.row(vs[i])));
  box.min().array() -= margin;
  box.max().array() += margin;
  return box;
}

// Cell size: the search radius, but not below the mean edge length, so that a triangle is
// listed in a few cells only.
double cell_size(const SelfContactModel& model, const MatrixX3d& x, double radius) {
  double sum = 0.0;
  for (const auto& e : model.edges) sum += (x.row(e[0]) - x.row(e[1])).norm();
  const double mean = model.edges.empty() ? 0.0 : sum / static_cast<double>(model.edges.size());
  return std::max({radius, mean, 1e-6});
}

bool excluded(const SelfContactModel& model, int v, const int* corners, int count) {
  const std::vector<int>& near = model.near[static_cast<size_t>(v)];
  for (int i = 0; i < count; ++i)
    if (std::binary_search(near.begin(), near.end(), corners[i])) return true;
  return false;
}

} // namespace

double segment_segment_distance(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1) {
  return segment_closest_parameters(p0, p1, q0, q1).distance;
}

SegmentClosestPoints segment_closest_parameters(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1) {
  // Ericson, Real-Time Collision Detection (2005), 5.1.9, degenerate segments included.
  const Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a > 0.0 && e <= 0.0) {
    s = std::clamp(-d1.dot(r) / a, 0.0, 1.0);
  } else if (a <= 0.0 && e > 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else if (a > 0.0 && e > 0.0) {
    const double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
    s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
      t = 1.0;
      s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return {s, t, (p0 + s * d1 - q0 - t * d2).norm()};
}

Element12 edge_edge_penalty(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1, double thickness,
                            double k, bool want_hessian) {
  Element12 out;
  out.energy = 0.0;
  out.gradient.setZero();
  out.hessian.setZero();
  const SegmentClosestPoints closest = segment_closest_parameters(p0, p1, q0, q1);
  if (!(closest.distance < thickness) || !(closest.distance > 0.0)) return out;
  Vec12 q;
  q << p0, p1, q0, q1;
  // The squared distance by the formula of the closest points' features: interior-interior is
  // the distance between the lines, an end against the other edge's interior is point-line,
  // two ends point-point. They agree to first order where the features change.
  const bool s_inside = closest.s > 0.0 && closest.s < 1.0, t_inside = closest.t > 0.0 && closest.t < 1.0;
  const int p_end = closest.s <= 0.0 ? 0 : 1, q_end = closest.t <= 0.0 ? 2 : 3;
  Hyper squared;
  const Hyper3 u = minus(corner(q, 1), corner(q, 0)), v = minus(corner(q, 3), corner(q, 2));
  const Hyper3 n = cross(u, v);
  const Hyper skew = dot(n, n);
  if (s_inside && t_inside) {
    const Hyper h = dot(minus(corner(q, 0), corner(q, 2)), n);
    squared = h * h * reciprocal(skew);
  } else if (t_inside) {
    squared = point_line_squared(q, p_end, 2, 3);
  } else if (s_inside) {
    squared = point_line_squared(q, q_end, 0, 1);
  } else {
    const Hyper3 r = minus(corner(q, p_end), corner(q, q_end));
    squared = dot(r, r);
  }
  const Hyper gap = constant(thickness) - root(squared);
  Hyper energy = constant(0.5 * k) * gap * gap;
  const Hyper y = skew * reciprocal(constant(kMollifier) * dot(u, u) * dot(v, v));
  if (y.v < 1.0) energy = energy * y * (constant(2.0) - y);
  out.energy = energy.v;
  out.gradient = energy.g;
  if (want_hessian) out.hessian = energy.H;
  return out;
}

Element12 point_triangle_penalty(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c, double thickness,
                                 double k, bool want_hessian) {
  Element12 out;
  out.gradient.setZero();
  if (want_hessian) out.hessian.setZero();
  const TriangleClosestPoint closest = closest_point_on_triangle(p, a, b, c);
  const Vector3d w = closest.weights;
  const Vector3d offset = p - w(0) * a - w(1) * b - w(2) * c;
  const double d = offset.norm();
  if (d >= thickness) return out;
  out.energy = 0.5 * k * (thickness - d) * (thickness - d);
  if (!(d > 0.0)) return out;  // touching: the direction is undefined, and so are the forces
  // dE/dd = -k (t - d); d's gradient: the unit offset at p, minus the weights at the corners
  // (the closest point moves along the triangle, which changes d only to second order).
  const Vector3d n = offset / d;
  out.gradient << n, -w(0) * n, -w(1) * n, -w(2) * n;
  out.gradient *= -k * (thickness - d);
  if (want_hessian) {
    Vec12 q;
    q << p, a, b, c;
    const Hyper s = squared_distance(q, closest.feature);
    // d = sqrt(s), E = k/2 (t - d)^2: E'(s) = -k (t - d) / (2 d), E''(s) = k t / (4 d^3).
    out.hessian = -k * (thickness - d) / (2.0 * d) * s.H + k * thickness / (4.0 * d * d * d) * s.g * s.g.transpose();
  }
  return out;
}

std::vector<std::array<int, 2>> self_contact_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius) {
  CellGrid grid(cell_size(model, x, radius));
  for (size_t t = 0; t < model.triangles.size(); ++t) grid.insert(box_of(x, model.triangles[t].data(), 3, radius), static_cast<int>(t));
  grid.finish();
  std::vector<std::array<int, 2>> pairs;
  for (int v : model.vertices) {
    const Vector3d p = x.row(v);
    grid.query(Eigen::AlignedBox3d(p, p), [&](int t) {
      const auto& tri = model.triangles[static_cast<size_t>(t)];
      if (excluded(model, v, tri.data(), 3)) return;
      if (point_triangle_distance(p, x.row(tri[0]), x.row(tri[1]), x.row(tri[2])) < radius) pairs.push_back({v, t});
    });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::array<int, 2>> self_contact_edge_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius) {
  CellGrid grid(cell_size(model, x, radius));
  for (size_t e = 0; e < model.edges.size(); ++e) grid.insert(box_of(x, model.edges[e].data(), 2, radius), static_cast<int>(e));
  grid.finish();
  std::vector<std::array<int, 2>> pairs;
  std::vector<int> seen(model.edges.size(), -1);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const auto& a = model.edges[e];
    grid.query(box_of(x, a.data(), 2, 0.0), [&](int f) {
      if (f <= static_cast<int>(e) || seen[static_cast<size_t>(f)] == static_cast<int>(e)) return;
      seen[static_cast<size_t>(f)] = static_cast<int>(e);
      const auto& b = model.edges[static_cast<size_t>(f)];
      if (excluded(model, a[0], b.data(), 2) || excluded(model, a[1], b.data(), 2)) return;
      if (segment_segment_distance(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1])) < radius) pairs.push_back({static_cast<int>(e), f});
    });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::array<int, 2>> self_contact_active_pairs(const SelfContactModel& model, const MatrixX3d& x) {
  const std::vector<std::array<int, 2>> pairs = self_contact_pairs(model, x, model.thickness);
  std::vector<std::array<int, 2>> out;
  std::vector<std::pair<double, int>> candidates;
  for (size_t begin = 0, end = 0; begin < pairs.size(); begin = end) {
    const int v = pairs[begin][0];
    candidates.clear();
    for (end = begin; end < pairs.size() && pairs[end][0] == v; ++end) {
      const auto& tri = model.triangles[static_cast<size_t>(pairs[end][1])];
      candidates.push_back({point_triangle_distance(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2])), pairs[end][1]});
    }
    std::sort(candidates.begin(), candidates.end());
    const size_t first = out.size();
    for (const auto& [distance, t] : candidates) {
      const auto& tri = model.triangles[static_cast<size_t>(t)];
      bool same_layer = false;
      for (size_t k = first; k < out.size() && !same_layer; ++k)
        for (int c : model.triangles[static_cast<size_t>(out[k][1])])
          same_layer = same_layer || c == tri[0] || c == tri[1] || c == tri[2];
      if (!same_layer) out.push_back({v, t});
    }
  }
  return out;
}

double self_contact_step_bound(const SelfContactModel& model, const MatrixX3d& x, const MatrixX3d& dx, double keep) {
  double largest = 0.0;
  for (int v : model.vertices) largest = std::max(largest, dx.row(v).norm());
  if (!(largest > 0.0)) return 1.0;
  // Two elements close in on each other by at most twice the largest move: pairs farther apart
  // than this cannot come within `keep` of their distance.
  const double radius = 2.0 * largest / (1.0 - keep);
  double alpha = 1.0;
  const auto limit = [&](double distance, double relative_move) {
    if (distance > 0.0 && relative_move > 0.0) alpha = std::min(alpha, (1.0 - keep) * distance / relative_move);
  };
  for (const auto& [v, t] : self_contact_pairs(model, x, radius)) {
    const auto& tri = model.triangles[static_cast<size_t>(t)];
    double move = 0.0;
    for (int c : tri) move = std::max(move, (dx.row(v) - dx.row(c)).norm());
    limit(point_triangle_distance(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2])), move);
  }
  for (const auto& [e, f] : self_contact_edge_pairs(model, x, radius)) {
    const auto &a = model.edges[static_cast<size_t>(e)], &b = model.edges[static_cast<size_t>(f)];
    double move = 0.0;
    for (int i : a)
      for (int j : b) move = std::max(move, (dx.row(i) - dx.row(j)).norm());
    limit(segment_segment_distance(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1])), move);
  }
  return alpha;
}

} // namespace foldsketch
