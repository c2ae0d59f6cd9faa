#include "sim/self_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>

#include <Eigen/Geometry>

namespace foldsketch {
namespace {


// A value with its gradient and, when Second, its Hessian over 9 variables, carried through
// each operation (forward differentiation). The penalties depend on their four corners only
// through three differences of them (they do not change when the pair is translated), so the
// variables are those differences (a 9 x 9 Hessian instead of 12 x 12: half the flops), and
// the result is lifted to the corners at the end (lift). The distance formulas below are
// short, so this costs a few thousand flops per pair with the Hessian (a few hundred without)
// and cannot disagree with them.
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
struct NoHessian {};
template <bool Second>
struct Jet {
  double v = 0;
  Vec9 g = Vec9::Zero();
  std::conditional_t<Second, Mat9, NoHessian> H = zero();

private:
  static auto zero() {
    if constexpr (Second) return Mat9::Zero().eval();
    else return NoHessian{};
  }
};
template <bool S>
using Jet3 = std::array<Jet<S>, 3>;
// Four corners' positions relative to one of them, as functions of the variables.
template <bool S>
using Corners = std::array<Jet3<S>, 4>;

// Edge-edge mollifier (Li et al. 2020, Incremental Potential Contact, section 4.3): the pair's
// energy fades smoothly to zero as the edges turn parallel, below |u x v|^2 = kMollifier |u|^2
// |v|^2, where their closest points are ill-defined.
constexpr double kMollifier = 1e-3;

template <bool S>
Jet<S> operator+(const Jet<S>& a, const Jet<S>& b) {
  Jet<S> r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  if constexpr (S) r.H = a.H + b.H;
  return r;
}
template <bool S>
Jet<S> operator-(const Jet<S>& a, const Jet<S>& b) {
  Jet<S> r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  if constexpr (S) r.H = a.H - b.H;
  return r;
}
template <bool S>
Jet<S> operator*(const Jet<S>& a, const Jet<S>& b) {
  Jet<S> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  if constexpr (S) {
    const Mat9 outer = a.g * b.g.transpose();
    r.H = a.v * b.H + b.v * a.H + outer + outer.transpose();
  }
  return r;
}
// f(a) from f(a.v), f'(a.v), f''(a.v).
template <bool S>
Jet<S> chain(const Jet<S>& a, double f, double f1, double f2) {
  Jet<S> r;
  r.v = f;
  r.g = f1 * a.g;
  if constexpr (S) r.H = f1 * a.H + f2 * a.g * a.g.transpose();
  return r;
}
template <bool S>
Jet<S> reciprocal(const Jet<S>& a) {
  return chain(a, 1.0 / a.v, -1.0 / (a.v * a.v), 2.0 / (a.v * a.v * a.v));
}
template <bool S>
Jet<S> constant(double value) {
  Jet<S> r;
  r.v = value;
  return r;
}

// Variables 3 b .. 3 b + 2 of z, as a vector.
template <bool S>
Jet3<S> variable(const Vec9& z, int b) {
  Jet3<S> out;
  for (int c = 0; c < 3; ++c) {
    out[c].v = z(3 * b + c);
    out[c].g(3 * b + c) = 1.0;
  }
  return out;
}
template <bool S>
Jet3<S> minus(const Jet3<S>& a, const Jet3<S>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <bool S>
Jet3<S> plus(const Jet3<S>& a, const Jet3<S>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <bool S>
Jet<S> dot(const Jet3<S>& a, const Jet3<S>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <bool S>
Jet3<S> cross(const Jet3<S>& a, const Jet3<S>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The variables as differences of the corners: variable block b = sum_k C(b, k) x_k. Lifts a
// gradient and Hessian over them to the 12 corner coordinates (J = C (x) I3: g J, J^T H J).
using Lift = Eigen::Matrix<double, 3, 4>;
Eigen::Matrix<double, 9, 12> lift_matrix(const Lift& C) {
  Eigen::Matrix<double, 9, 12> J = Eigen::Matrix<double, 9, 12>::Zero();
  for (int b = 0; b < 3; ++b)
    for (int k = 0; k < 4; ++k) J.block<3, 3>(3 * b, 3 * k) = C(b, k) * Eigen::Matrix3d::Identity();
  return J;
}
// Edge-edge (x0, x1, x2, x3): u = x1 - x0, v = x3 - x2, w = x0 - x2.
const Lift kEdgeEdgeLift = (Lift() << -1, 1, 0, 0, 0, 0, -1, 1, 1, 0, -1, 0).finished();
// Point-triangle (p, a, b, c): r = p - a, e1 = b - a, e2 = c - a.
const Lift kPointTriangleLift = (Lift() << 1, -1, 0, 0, 0, -1, 1, 0, 0, -1, 0, 1).finished();

// Squared distance from corner i to the line through corners j, k.
template <bool S>
Jet<S> point_line_squared(const Corners<S>& X, int i, int j, int k) {
  const Jet3<S> e = minus(X[k], X[j]);
  const Jet3<S> r = cross(minus(X[i], X[j]), e);
  return dot(r, r) * reciprocal(dot(e, e));
}

// Squared distance from p to the given feature of triangle (a, b, c), with its gradient and
// Hessian over (p - a, b - a, c - a): each formula is smooth inside its feature's region, and
// they agree to first order where regions meet.
Jet<true> squared_distance(const Vec9& z, int feature) {
  const Jet3<true> zero{};
  const Corners<true> X{variable<true>(z, 0), zero, variable<true>(z, 1), variable<true>(z, 2)};
  if (feature == 0) {  // face: ((p - a).n)^2 / |n|^2
    const Jet3<true> n = cross(X[2], X[3]);
    const Jet<true> h = dot(X[0], n);
    return h * h * reciprocal(dot(n, n));
  }
  if (feature <= 3) return point_line_squared<true>(X, 0, feature, feature % 3 + 1);  // edge
  return dot(minus(X[0], X[feature - 3]), minus(X[0], X[feature - 3]));                // corner
}

// The edge-edge penalty with its gradient and, when S, its Hessian over (u, v, w)
// (edge_edge_penalty).
template <bool S>
Jet<S> edge_edge_jet(const Vec9& z, const SegmentClosestPoints& closest, double thickness, double k) {
  // The squared distance by the formula of the closest points' features: interior-interior is
  // the distance between the lines, an end against the other edge's interior is point-line,
  // two ends point-point. They agree to first order where the features change.
  const bool s_inside = closest.s > 0.0 && closest.s < 1.0, t_inside = closest.t > 0.0 && closest.t < 1.0;
  const int p_end = closest.s <= 0.0 ? 0 : 1, q_end = closest.t <= 0.0 ? 2 : 3;
  const Jet3<S> u = variable<S>(z, 0), v = variable<S>(z, 1), w = variable<S>(z, 2);
  const Corners<S> X{w, plus(w, u), Jet3<S>{}, v};  // relative to x2
  std::optional<Jet<S>> skew;  // |u x v|^2, when the case needs it
  Jet<S> squared;
  if (s_inside && t_inside) {
    const Jet3<S> n = cross(u, v);
    skew = dot(n, n);
    const Jet<S> h = dot(w, n);
    squared = h * h * reciprocal(*skew);
  } else if (t_inside) {
    squared = point_line_squared<S>(X, p_end, 2, 3);
  } else if (s_inside) {
    squared = point_line_squared<S>(X, q_end, 0, 1);
  } else {
    const Jet3<S> r = minus(X[p_end], X[q_end]);
    squared = dot(r, r);
  }
  // E = k/2 (t - d)^2, d = sqrt(squared): E'(s) = -k (t - d) / (2 d), E''(s) = k t / (4 d^3).
  const double d = std::sqrt(squared.v);
  Jet<S> energy = chain(squared, 0.5 * k * (thickness - d) * (thickness - d), -k * (thickness - d) / (2.0 * d),
                        k * thickness / (4.0 * d * d * d));
  // The mollifier, where the edges are nearly parallel (judged in plain numbers first).
  const Vector3d pu = z.segment<3>(0), pv = z.segment<3>(3);
  if (pu.cross(pv).squaredNorm() < kMollifier * pu.squaredNorm() * pv.squaredNorm()) {
    if (!skew) {
      const Jet3<S> n = cross(u, v);
      skew = dot(n, n);
    }
    const Jet<S> y = *skew * reciprocal(constant<S>(kMollifier) * dot(u, u) * dot(v, v));
    energy = energy * y * (constant<S>(2.0) - y);
  }
  return energy;
}

// Uniform grid of boxes, for the broad phase: items are listed in every cell their box
// touches, queries read the cells of a point or a box. The cells are hashed into a table of
// about twice as many slots as listings, filled by a counting sort (Teschner et al. 2003,
// "Optimized spatial hashing for collision detection of deformable objects"); cells that share
// a slot only add candidates, which the callers' exact tests reject. Measured on a pleat of 560
// vertices: a sorted list of (cell, item) searched by bisection spent a third of the pair
// searches sorting.
class CellGrid {
public:
  explicit CellGrid(double cell) : cell_(cell) {}
  void insert(const Eigen::AlignedBox3d& box, int item) {
    if (!box.min().allFinite() || !box.max().allFinite()) return;  // a NaN state: its energy is NaN anyway
    const Eigen::Vector3i lo = index(box.min()), hi = index(box.max());
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) listings_.push_back({hash({i, j, k}), item});
  }
  void finish() {
    uint64_t slots = 16;
    while (slots < 2 * listings_.size()) slots *= 2;
    mask_ = slots - 1;
    start_.assign(slots + 1, 0);
    for (const auto& [h, item] : listings_) ++start_[(h & mask_) + 1];
    for (size_t s = 0; s < slots; ++s) start_[s + 1] += start_[s];
    items_.resize(listings_.size());
    std::vector<int> next(start_.begin(), start_.end() - 1);
    for (const auto& [h, item] : listings_) items_[static_cast<size_t>(next[h & mask_]++)] = item;
    listings_.clear();
  }
  // Calls f(item) for every item listed in a cell touching `box` (an item may come repeatedly).
  template <typename F>
  void query(const Eigen::AlignedBox3d& box, F f) const {
    if (!box.min().allFinite() || !box.max().allFinite()) return;
    const Eigen::Vector3i lo = index(box.min()), hi = index(box.max());
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) {
          const uint64_t slot = hash({i, j, k}) & mask_;
          for (int at = start_[slot]; at < start_[slot + 1]; ++at) f(items_[static_cast<size_t>(at)]);
        }
  }

private:
  Eigen::Vector3i index(const Vector3d& p) const {
    // Clamped to +-1e6 cells (10 km at 1 cm cells), so that a runaway state cannot overflow.
    constexpr double kLimit = 1e6;
    return (p / cell_).array().floor().max(-kLimit).min(kLimit).cast<int>();
  }
  // The primes of Teschner et al.
  static uint64_t hash(const Eigen::Vector3i& c) {
    return static_cast<uint64_t>(static_cast<uint32_t>(c.x()) * 73856093u ^ static_cast<uint32_t>(c.y()) * 19349663u ^
                                 static_cast<uint32_t>(c.z()) * 83492791u);
  }
  double cell_;
  uint64_t mask_ = 0;
  std::vector<std::pair<uint64_t, int>> listings_;
  std::vector<int> start_, items_;
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
  Vec9 z;
  z << p1 - p0, q1 - q0, p0 - q0;
  static const Eigen::Matrix<double, 9, 12> J = lift_matrix(kEdgeEdgeLift);
  if (want_hessian) {
    const Jet<true> e = edge_edge_jet<true>(z, closest, thickness, k);
    out.energy = e.v;
    out.gradient = J.transpose() * e.g;
    out.hessian = J.transpose() * e.H * J;
  } else {
    const Jet<false> e = edge_edge_jet<false>(z, closest, thickness, k);
    out.energy = e.v;
    out.gradient = J.transpose() * e.g;
  }
  return out;
}

double edge_edge_energy(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1, double thickness, double k) {
  const double d = segment_segment_distance(p0, p1, q0, q1);
  if (!(d < thickness) || !(d > 0.0)) return 0.0;
  const Vector3d u = p1 - p0, v = q1 - q0;
  const double y = u.cross(v).squaredNorm() / (kMollifier * u.squaredNorm() * v.squaredNorm());
  const double energy = 0.5 * k * (thickness - d) * (thickness - d);
  return y < 1.0 ? energy * y * (2.0 - y) : energy;
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
    Vec9 z;
    z << p - a, b - a, c - a;
    static const Eigen::Matrix<double, 9, 12> J = lift_matrix(kPointTriangleLift);
    const Jet<true> s = squared_distance(z, closest.feature);
    // d = sqrt(s), E = k/2 (t - d)^2: E'(s) = -k (t - d) / (2 d), E''(s) = k t / (4 d^3).
    const Mat9 H = -k * (thickness - d) / (2.0 * d) * s.H + k * thickness / (4.0 * d * d * d) * s.g * s.g.transpose();
    out.hessian = J.transpose() * H * J;
  }
  return out;
}

std::vector<std::array<int, 2>> self_contact_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius) {
  CellGrid grid(cell_size(model, x, radius));
  std::vector<Eigen::AlignedBox3d> boxes(model.triangles.size());  // each triangle's, grown by the radius
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    boxes[t] = box_of(x, model.triangles[t].data(), 3, radius);
    grid.insert(boxes[t], static_cast<int>(t));
  }
  grid.finish();
  std::vector<std::array<int, 2>> pairs;
  for (int v : model.vertices) {
    const Vector3d p = x.row(v);
    grid.query(Eigen::AlignedBox3d(p, p), [&](int t) {
      if (!boxes[static_cast<size_t>(t)].contains(p)) return;  // farther than the radius along some axis
      const auto& tri = model.triangles[static_cast<size_t>(t)];
      if (excluded(model, v, tri.data(), 3)) return;
      if (point_triangle_distance(p, x.row(tri[0]), x.row(tri[1]), x.row(tri[2])) < radius) pairs.push_back({v, t});
    });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());  // cells sharing a hash slot
  return pairs;
}

std::vector<std::array<int, 2>> self_contact_edge_pairs(const SelfContactModel& model, const MatrixX3d& x, double radius) {
  CellGrid grid(cell_size(model, x, radius));
  std::vector<Eigen::AlignedBox3d> boxes(model.edges.size());  // each edge's, grown by the radius
  for (size_t e = 0; e < model.edges.size(); ++e) {
    boxes[e] = box_of(x, model.edges[e].data(), 2, radius);
    grid.insert(boxes[e], static_cast<int>(e));
  }
  grid.finish();
  std::vector<std::array<int, 2>> pairs;
  std::vector<int> seen(model.edges.size(), -1);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const auto& a = model.edges[e];
    const Eigen::AlignedBox3d box = box_of(x, a.data(), 2, 0.0);
    grid.query(box, [&](int f) {
      if (f <= static_cast<int>(e) || seen[static_cast<size_t>(f)] == static_cast<int>(e)) return;
      seen[static_cast<size_t>(f)] = static_cast<int>(e);
      if (!boxes[static_cast<size_t>(f)].intersects(box)) return;  // farther than the radius along some axis
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
