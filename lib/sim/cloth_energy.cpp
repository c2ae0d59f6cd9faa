#include "sim/cloth_energy.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include <exception>
#include <thread>
#include <utility>

#include "core/error.h"
#include "sim/bending.h"
#include "sim/self_contact.h"

namespace foldsketch {
namespace {

// Elements per thread below which a second thread costs more than it saves (our measure: a
// thread start is tens of microseconds, an element a few hundred nanoseconds).
constexpr size_t kElementsPerThread = 2000;
// Below this distance [m] from a body triangle the direction from its closest point is
// roundoff; the triangle's normal is used instead.
constexpr double kContactDirectionFloor = 1e-12;
// Self-contact pairs enter the Hessian pattern once closer than this many contact thicknesses,
// a little ahead of contact, so the pattern (and the analysis) changes less often.
constexpr double kPatternReach = 2.0;

// Share [begin, end) of thread `me` among `threads` in a loop of `count` items: contiguous,
// sizes differing by at most one.
std::pair<long, long> thread_share(size_t count, int me, int threads) {
  const auto t = static_cast<size_t>(threads), m = static_cast<size_t>(me);
  return {static_cast<long>(count * m / t), static_cast<long>(count * (m + 1) / t)};
}

// Runs work(0), ..., work(threads - 1), work(0) on the calling thread, the others on fresh
// threads that end when their share does. Plain threads instead of OpenMP: idle OpenMP workers
// spin between parallel regions and took CPU from CHOLMOD's BLAS threads on 2 cores (measured on
// the 5K skirt: factorisation 4.3 s vs 5.3 s over 150 iterations). Rethrows a worker's exception.
void run_in_threads(int threads, const std::function<void(int)>& work) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      try {
        work(t);
      } catch (...) {
        errors[static_cast<size_t>(t)] = std::current_exception();
      }
    });
  try {
    work(0);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

} // namespace

ClothEnergy::ClothEnergy(const ClothModel& model) : model_(model) {
  free_index_.assign(static_cast<size_t>(model.vertex_count), 0);
  for (const Pin& p : model.pins) free_index_[p.vertex] = -1;
  for (int v = 0; v < model.vertex_count; ++v) {
    if (free_index_[v] < 0) continue;
    free_index_[v] = static_cast<int>(free_vertices_.size());
    free_vertices_.push_back(v);
  }
  const int n = free_count();

  // Block pattern: every pair of free vertices that share an element, and every diagonal.
  neighbours_.assign(static_cast<size_t>(n), {});
  const auto couple = [&](const int* vs, int count) {
    for (int i = 0; i < count; ++i)
      for (int j = 0; j < count; ++j) {
        const int a = free_index_[vs[i]], b = free_index_[vs[j]];
        if (a >= 0 && b >= 0) neighbours_[b].push_back(a);
      }
  };
  for (int v = 0; v < n; ++v) neighbours_[v].push_back(v);
  for (const auto& t : model.triangles) couple(t.data(), 3);
  for (const Hinge& h : model.hinges) couple(h.v.data(), 4);
  for (const StitchSpring& s : model.stitches) couple(s.v.data(), 4);
  for (auto& rows : neighbours_) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }
  build_pattern();
  laplacians_.reserve(model.triangles.size());
  for (const MembraneRest& r : model.rest) {
    const Eigen::Matrix<double, 2, 3> b = shape_gradients(r);
    laplacians_.push_back(r.area * b.transpose() * b);
  }
  free_mass_.resize(3 * n);
  for (int v = 0; v < n; ++v) free_mass_.segment<3>(3 * v).setConstant(model.mass(free_vertices_[v]));
  const size_t elements = model.triangles.size() + model.hinges.size() + static_cast<size_t>(n);
  const size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  thread_count_ = static_cast<int>(std::clamp<size_t>(elements / kElementsPerThread, 1, hardware));
  contact_certificates_.assign(static_cast<size_t>(n), Eigen::Vector4d::Constant(std::numeric_limits<double>::quiet_NaN()));
}

void ClothEnergy::build_pattern() {
  const int n = free_count();
  pattern_ = SparseMatrix(3 * n, 3 * n);
  std::vector<int> outer(static_cast<size_t>(3 * n + 1), 0);
  for (int b = 0; b < n; ++b)
    for (int c = 0; c < 3; ++c) outer[3 * b + c + 1] = outer[3 * b + c] + 3 * static_cast<int>(neighbours_[b].size());
  pattern_.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  for (int b = 0; b < n; ++b)
    for (int c = 0; c < 3; ++c) {
      int at = outer[3 * b + c];
      for (int a : neighbours_[b])
        for (int r = 0; r < 3; ++r) pattern_.innerIndexPtr()[at++] = 3 * a + r;
    }
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);
  triangle_blocks_.clear();
  hinge_blocks_.clear();
  stitch_blocks_.clear();
  diagonal_blocks_.clear();
  for (const auto& t : model_.triangles) triangle_blocks_.push_back(blocks_for(t.data(), 3));
  for (const Hinge& h : model_.hinges) hinge_blocks_.push_back(blocks_for(h.v.data(), 4));
  for (const StitchSpring& s : model_.stitches) stitch_blocks_.push_back(blocks_for(s.v.data(), 4));
  for (int v = 0; v < n; ++v) diagonal_blocks_.push_back(block(v, v));
}

bool ClothEnergy::prepare(const MatrixX3d& x) {
  if (!model_.self_contact) return false;
  const SelfContactModel& sc = *model_.self_contact;
  if (prepared_at_.rows() == x.rows()) {
    double largest = 0.0;
    for (int v : sc.vertices) largest = std::max(largest, (x.row(v) - prepared_at_.row(v)).norm());
    if (largest <= 0.5 * (kPatternReach - 1.0) * sc.thickness) return false;
  }
  prepared_at_ = x;
  bool grew = false;
  const auto couple = [&](int a, int b) {  // free vertex indices
    auto& rows = neighbours_[b];
    const auto at = std::lower_bound(rows.begin(), rows.end(), a);
    if (at != rows.end() && *at == a) return;
    rows.insert(at, a);
    grew = true;
  };
  for (const auto& [v, t] : self_contact_pairs(sc, x, kPatternReach * sc.thickness)) {
    const int a = free_index_[v];
    if (a < 0) continue;
    for (int c : sc.triangles[static_cast<size_t>(t)])
      if (const int b = free_index_[c]; b >= 0) {
        couple(a, b);
        couple(b, a);
      }
  }
  for (const auto& [e, f] : self_contact_edge_pairs(sc, x, kPatternReach * sc.thickness)) {
    const auto &a = sc.edges[static_cast<size_t>(e)], &b = sc.edges[static_cast<size_t>(f)];
    const int vs[4] = {free_index_[a[0]], free_index_[a[1]], free_index_[b[0]], free_index_[b[1]]};
    for (int i : vs)
      for (int j : vs)
        if (i >= 0 && j >= 0) couple(i, j);
  }
  if (grew) build_pattern();
  return grew;
}

// Block (a, b) entry (r, c) lives at base + c * stride + r: every column of block column b
// holds the same block rows, three entries each.
ClothEnergy::Block ClothEnergy::block(int a, int b) const {
  const auto& rows = neighbours_[b];
  const auto at = std::lower_bound(rows.begin(), rows.end(), a);
  if (at == rows.end() || *at != a) throw std::logic_error("ClothEnergy: a Hessian block outside the pattern (prepare() was not called)");
  const int rank = static_cast<int>(at - rows.begin());
  return {pattern_.outerIndexPtr()[3 * b] + 3 * rank, 3 * static_cast<int>(rows.size())};
}

std::vector<ClothEnergy::Block> ClothEnergy::blocks_for(const int* vs, int count) const {
  std::vector<Block> out(static_cast<size_t>(count * count));
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i) {
      const int a = free_index_[vs[i]], b = free_index_[vs[j]];
      if (a >= 0 && b >= 0) out[static_cast<size_t>(j * count + i)] = block(a, b);
    }
  return out;
}

template <int N>
void ClothEnergy::scatter(const std::vector<Block>& blocks, const Eigen::Matrix<double, 3 * N, 3 * N>& H, double* values) const {
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      const Block& b = blocks[static_cast<size_t>(j * N + i)];
      if (b.base < 0) continue;
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) values[b.base + c * b.stride + r] += H(3 * i + r, 3 * j + c);
    }
}

EnergyTerms ClothEnergy::evaluate(const MatrixX3d& x, VectorXd* gradient, SparseMatrix* hessian, HessianKind membrane_kind,
                                  HessianKind bending_kind, HessianKind contact_kind) const {
  if (x.rows() != model_.vertex_count) throw ArgumentError("ClothEnergy: drape has the wrong number of vertices");
  const bool want_gradient = gradient != nullptr, want_hessian = hessian != nullptr;
  const bool exact_contact = contact_kind == HessianKind::Exact;
  if (want_hessian && (hessian->nonZeros() != pattern_.nonZeros() || hessian->rows() != pattern_.rows())) *hessian = pattern_;
  const int n = free_count();
  const long value_count = want_hessian ? hessian->nonZeros() : 0;
  EnergyTerms terms;
  // Each thread takes a contiguous share of every element loop and accumulates into its own
  // gradient and Hessian values; they are summed after, in thread order (deterministic).
  const int threads = thread_count_;
  // Thread 0 accumulates straight into the outputs, the others into buffers each zeroes itself.
  std::vector<VectorXd> thread_gradients(static_cast<size_t>(threads));
  std::vector<std::vector<double>> thread_values(static_cast<size_t>(threads));
  std::vector<EnergyTerms> thread_terms(static_cast<size_t>(threads));
  const SelfContactModel* sc = model_.self_contact ? &*model_.self_contact : nullptr;
  const std::vector<std::array<int, 2>> self_pairs = sc ? self_contact_active_pairs(*sc, x) : std::vector<std::array<int, 2>>{};
  const std::vector<std::array<int, 2>> edge_pairs = sc ? self_contact_edge_pairs(*sc, x, sc->thickness) : std::vector<std::array<int, 2>>{};
  const auto work = [&](int me_int) {
    const auto me = static_cast<size_t>(me_int);
    VectorXd& grad = me == 0 && want_gradient ? *gradient : thread_gradients[me];
    if (want_gradient) grad.setZero(3 * n);
    double* values = nullptr;
    if (want_hessian) {
      if (me == 0) {
        values = hessian->valuePtr();
        std::fill(values, values + value_count, 0.0);
      } else {
        thread_values[me].assign(static_cast<size_t>(value_count), 0.0);
        values = thread_values[me].data();
      }
    }
    EnergyTerms& mine = thread_terms[me];
    const auto add_gradient = [&](const int* vs, int count, const auto& g) {
      if (!want_gradient) return;
      for (int i = 0; i < count; ++i)
        if (const int a = free_index_[vs[i]]; a >= 0) grad.segment<3>(3 * a) += g.template segment<3>(3 * i);
    };
    const auto share = [&](size_t count) { return thread_share(count, me_int, threads); };
    const bool energy_only = !want_gradient && !want_hessian;
    for (auto [t, end] = share(model_.triangles.size()); t < end; ++t) {
      const auto& v = model_.triangles[static_cast<size_t>(t)];
      if (energy_only) {
        mine.membrane += membrane_energy(x.row(v[0]), x.row(v[1]), x.row(v[2]), model_.rest[static_cast<size_t>(t)], model_.stiffness);
        continue;
      }
      const Element9 e = membrane_element(x.row(v[0]), x.row(v[1]), x.row(v[2]), model_.rest[static_cast<size_t>(t)],
                                          model_.stiffness, want_hessian, membrane_kind);
      mine.membrane += e.energy;
      add_gradient(v.data(), 3, e.gradient);
      if (want_hessian) scatter<3>(triangle_blocks_[static_cast<size_t>(t)], e.hessian, values);
    }
    for (auto [h, end] = share(model_.hinges.size()); h < end; ++h) {
      const Hinge& hinge = model_.hinges[static_cast<size_t>(h)];
      const auto& v = hinge.v;
      if (energy_only) {
        mine.bending += hinge_energy(x.row(v[0]), x.row(v[1]), x.row(v[2]), x.row(v[3]), hinge.stiffness, hinge.rest_angle);
        continue;
      }
      const Element12 e = hinge_element(x.row(v[0]), x.row(v[1]), x.row(v[2]), x.row(v[3]), hinge.stiffness, hinge.rest_angle,
                                        want_hessian, bending_kind);
      mine.bending += e.energy;
      add_gradient(v.data(), 4, e.gradient);
      if (want_hessian) scatter<4>(hinge_blocks_[static_cast<size_t>(h)], e.hessian, values);
    }
    for (auto [s, end] = share(model_.stitches.size()); s < end; ++s) {
      // E = k/2 |sum_i w_i x_i|^2 (b's weights negative): quadratic, exact Hessian k w w^T (x) I.
      const StitchSpring& st = model_.stitches[static_cast<size_t>(s)];
      Vector3d gap = Vector3d::Zero();
      for (int i = 0; i < 4; ++i) gap += st.w[i] * x.row(st.v[i]).transpose();
      mine.stitches += 0.5 * model_.stitch_stiffness * gap.squaredNorm();
      Eigen::Matrix<double, 12, 1> g;
      for (int i = 0; i < 4; ++i) g.segment<3>(3 * i) = model_.stitch_stiffness * st.w[i] * gap;
      add_gradient(st.v.data(), 4, g);
      if (want_hessian) {
        Eigen::Matrix<double, 12, 12> H = Eigen::Matrix<double, 12, 12>::Zero();
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            H.block<3, 3>(3 * i, 3 * j) = model_.stitch_stiffness * st.w[i] * st.w[j] * Eigen::Matrix3d::Identity();
        scatter<4>(stitch_blocks_[static_cast<size_t>(s)], H, values);
      }
    }
    for (auto [i, end] = share(self_pairs.size()); i < end; ++i) {
      const auto [v, t] = self_pairs[static_cast<size_t>(i)];
      const auto& tri = sc->triangles[static_cast<size_t>(t)];
      const std::array<int, 4> vs{v, tri[0], tri[1], tri[2]};
      const Element12 e = point_triangle_penalty(x.row(v), x.row(tri[0]), x.row(tri[1]), x.row(tri[2]), sc->thickness,
                                                 sc->stiffness * model_.contact_area(v), want_hessian);
      mine.self_contact += e.energy;
      add_gradient(vs.data(), 4, e.gradient);
      if (want_hessian) scatter<4>(blocks_for(vs.data(), 4), e.hessian, values);
    }
    for (auto [i, end] = share(edge_pairs.size()); i < end; ++i) {
      const auto& a = sc->edges[static_cast<size_t>(edge_pairs[static_cast<size_t>(i)][0])];
      const auto& b = sc->edges[static_cast<size_t>(edge_pairs[static_cast<size_t>(i)][1])];
      const std::array<int, 4> vs{a[0], a[1], b[0], b[1]};
      // An edge pair's area share: a third of its vertices' mean share (a mesh has about three
      // edges per vertex), so edges and vertices weigh alike.
      double area = 0.0;
      for (int v : vs) area += model_.contact_area(v) / 12.0;
      if (energy_only) {
        mine.self_contact +=
            edge_edge_energy(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1]), sc->thickness, sc->stiffness * area);
        continue;
      }
      const Element12 e = edge_edge_penalty(x.row(a[0]), x.row(a[1]), x.row(b[0]), x.row(b[1]), sc->thickness, sc->stiffness * area,
                                            want_hessian);
      mine.self_contact += e.energy;
      add_gradient(vs.data(), 4, e.gradient);
      if (want_hessian) scatter<4>(blocks_for(vs.data(), 4), e.hessian, values);
    }
    // Gravity and contact act per vertex; pinned vertices do not move, so only free ones count.
    for (auto [a, end] = share(static_cast<size_t>(n)); a < end; ++a) {
      const int v = free_vertices_[a];
      const Vector3d p = x.row(v);
      mine.gravity -= model_.mass(v) * model_.gravity.dot(p);
      if (want_gradient) grad.segment<3>(3 * a) -= model_.mass(v) * model_.gravity;
      if (!model_.body) continue;
      // Out of contact by a certificate: the segment from the certified point to p stays more
      // than the thickness away from the body, so p cannot have crossed it (closed bodies).
      Eigen::Vector4d& certificate = contact_certificates_[static_cast<size_t>(a)];
      if (certificate.w() - (p - certificate.head<3>()).norm() > model_.contact_thickness) continue;
      const BodyPoint b = model_.body->at(p);
      certificate << p, b.distance;
      if (b.distance >= model_.contact_thickness) continue;
      // One-sided penalty E = k A / 2 (t - d)^2 on the distance d to the body. d has a kink
      // wherever the closest point jumps, at every concave crease of the body mesh, and Newton
      // stalls in that V (a 14K-triangle skirt stopped at residual 1.3e-3). Near a concave
      // crease the penalty is therefore summed over the body's faces, edges and corners within
      // t, weighted +1, -1, +1: that sum is C1, and it is the closest-point penalty wherever the
      // body is convex or flat (BodyDistance::contact_features). Inside the body, d is signed
      // and the closest point alone pushes the vertex out. Hessian per term k A (u u^T - (t - d)
      // H_d), u = grad d, H_d = 0 from a face's interior, (I - u u^T - e e^T) / d from an edge e,
      // (I - u u^T) / d from a corner (which one: BodyPoint, BodyFeaturePoint). H_d is PSD, so
      // for the terms counted +1 its part is negative: a vertex on a convex edge or corner of the
      // body is softer sideways. contact_kind Exact keeps it; otherwise it is dropped there
      // (Gauss-Newton on d) and kept for the edges counted -1, where it is positive, so the
      // Hessian is exact at a concave crease. Why both: DrapeSettings::exact_contact_residual.
      const double t = model_.contact_thickness;
      const double k = model_.contact_stiffness * model_.contact_area(v);
      std::vector<BodyFeaturePoint> terms_here;
      if (b.distance > 0.0) terms_here = model_.body->contact_features(p, t);
      if (terms_here.empty()) {
        BodyFeaturePoint closest{b.closest};
        if (want_hessian && exact_contact) {  // where on the face it lies: the distance's curvature
          const BodyFeaturePoint on = model_.body->closest_on_face(p, b.face);
          closest.edge = on.edge;
          closest.on_face = on.on_face;
        }
        terms_here.push_back(closest);
      }
      const double sign = b.distance < 0.0 ? -1.0 : 1.0;
      for (const BodyFeaturePoint& f : terms_here) {
        const Vector3d offset = p - f.closest;
        const double distance = offset.norm();
        const double depth = t - sign * distance;
        if (depth <= 0.0) continue;
        const bool on_surface = !(distance > kContactDirectionFloor);
        const Vector3d u = on_surface ? b.normal : Vector3d(sign * offset / distance);  // grad of the signed d
        mine.contact += f.weight * 0.5 * k * depth * depth;
        if (want_gradient) grad.segment<3>(3 * a) -= f.weight * k * depth * u;
        if (want_hessian) {
          Eigen::Matrix3d H = k * u * u.transpose();
          if ((f.weight < 0.0 || exact_contact) && !on_surface && !f.on_face)  // curvature of the distance
            H -= k * depth * sign * (Eigen::Matrix3d::Identity() - u * u.transpose() - f.edge * f.edge.transpose()) / distance;
          H *= f.weight;
          const Block& d = diagonal_blocks_[static_cast<size_t>(a)];
          for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) values[d.base + c * d.stride + r] += H(r, c);
        }
      }
    }
  };
  run_in_threads(threads, work);
  for (const EnergyTerms& t : thread_terms) {
    terms.membrane += t.membrane;
    terms.bending += t.bending;
    terms.gravity += t.gravity;
    terms.stitches += t.stitches;
    terms.contact += t.contact;
    terms.self_contact += t.self_contact;
  }
  // Sums in thread order (deterministic), each thread over its own range of the outputs.
  if (threads > 1 && (want_gradient || want_hessian))
    run_in_threads(threads, [&](int me) {
      if (want_gradient) {
        const auto [begin, end] = thread_share(3 * static_cast<size_t>(n), me, threads);
        for (int t = 1; t < threads; ++t) gradient->segment(begin, end - begin) += thread_gradients[static_cast<size_t>(t)].segment(begin, end - begin);
      }
      if (want_hessian) {
        const auto [begin, end] = thread_share(static_cast<size_t>(value_count), me, threads);
        double* out = hessian->valuePtr();
        for (int t = 1; t < threads; ++t) {
          const double* v = thread_values[static_cast<size_t>(t)].data();
          for (long i = begin; i < end; ++i) out[i] += v[i];
        }
      }
    });
  return terms;
}

VectorXd ClothEnergy::gravity_force() const {
  VectorXd f(3 * free_count());
  for (int a = 0; a < free_count(); ++a) f.segment<3>(3 * a) = model_.mass(free_vertices_[a]) * model_.gravity;
  return f;
}

void ClothEnergy::add_mass(SparseMatrix& A, double lambda) const {
  double* values = A.valuePtr();
  for (int a = 0; a < free_count(); ++a) {
    const Block& d = diagonal_blocks_[static_cast<size_t>(a)];
    for (int r = 0; r < 3; ++r) values[d.base + r * d.stride + r] += lambda * free_mass_(3 * a + r);
  }
}

void ClothEnergy::add_laplacian(SparseMatrix& A, double mu_all, const VectorXd* weights) const {
  double* values = A.valuePtr();
  for (size_t t = 0; t < laplacians_.size(); ++t) {
    const double mu = weights ? mu_all * (*weights)(static_cast<Eigen::Index>(t)) : mu_all;
    const auto& blocks = triangle_blocks_[t];
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const Block& b = blocks[static_cast<size_t>(j * 3 + i)];
        if (b.base < 0) continue;
        for (int r = 0; r < 3; ++r) values[b.base + r * b.stride + r] += mu * laplacians_[t](i, j);
      }
  }
}

SparseMatrix ClothEnergy::scalar_laplacian() const {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * laplacians_.size());
  for (size_t t = 0; t < laplacians_.size(); ++t) {
    const auto& v = model_.triangles[t];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int a = free_index_[v[i]], b = free_index_[v[j]];
        if (a >= 0 && b >= 0) entries.emplace_back(a, b, laplacians_[t](i, j));
      }
  }
  SparseMatrix L(free_count(), free_count());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

VectorXd ClothEnergy::laplacian_times(const VectorXd& d, const VectorXd* weights) const {
  VectorXd y = VectorXd::Zero(d.size());
  for (size_t t = 0; t < laplacians_.size(); ++t) {
    const auto& v = model_.triangles[t];
    const double w = weights ? (*weights)(static_cast<Eigen::Index>(t)) : 1.0;
    for (int i = 0; i < 3; ++i) {
      const int a = free_index_[v[i]];
      if (a < 0) continue;
      for (int j = 0; j < 3; ++j)
        if (const int b = free_index_[v[j]]; b >= 0) y.segment<3>(3 * a) += w * laplacians_[t](i, j) * d.segment<3>(3 * b);
    }
  }
  return y;
}

VectorXd ClothEnergy::compressive_stress(const MatrixX3d& x) const {
  VectorXd c(static_cast<Eigen::Index>(model_.triangles.size()));
  for (size_t t = 0; t < model_.triangles.size(); ++t) {
    const auto& v = model_.triangles[t];
    const Eigen::Matrix2d S = membrane_stress(x.row(v[0]), x.row(v[1]), x.row(v[2]), model_.rest[t], model_.stiffness);
    // The smaller eigenvalue of the symmetric 2x2 stress, in closed form (once per triangle and
    // Newton iteration).
    const double mean = 0.5 * (S(0, 0) + S(1, 1)), half_difference = 0.5 * (S(0, 0) - S(1, 1));
    const double least = mean - std::hypot(half_difference, S(0, 1));
    c(static_cast<Eigen::Index>(t)) = std::max(0.0, -least);
  }
  return c;
}

} // namespace foldsketch
