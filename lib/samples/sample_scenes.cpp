#include "samples/sample_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "core/error.h"
#include "samples/cone_panels.h"
#include "samples/grid_garment.h"

namespace foldsketch {
namespace {

// Drape nodes of different panels closer than this are one sewn vertex [m].
constexpr double kWeldTolerance = 1e-7;
// Pins are the vertices within this distance of the pinned line or ring [m].
constexpr double kPinSlack = 1e-4;
// Gap between panels laid out in pattern space [m].
constexpr double kLayoutGap = 0.05;
// Rounds of correcting the grid spacing of a tube by its actual triangle count: column and
// row counts are whole numbers, so the first guess from the area misses by up to ~10 %.
constexpr int kSizingRounds = 3;

int divisions(double length, double h) { return std::max(1, static_cast<int>(std::lround(length / h))); }

// Edge length giving about `triangles` right-triangle pairs over `area`.
double grid_spacing(double area, int triangles) { return std::sqrt(2.0 * area / std::max(triangles, 2)); }

// The garment of the laid-out panels, meshed as asked. The isotropic lattice spacing gives
// about params.triangles equilateral triangles over the panels' area: N = A / (sqrt(3)/4 s^2).
Garment mesh_panels(const std::vector<GridPanel>& panels, const SampleParams& params) {
  const Garment grid = grid_garment(panels, kWeldTolerance);
  if (params.mesh == SampleMesh::Grid) return grid;
  double area = 0.0;
  for (int f = 0; f < grid.FP.rows(); ++f) {
    const Vector2d a = grid.P.row(grid.FP(f, 0)), b = grid.P.row(grid.FP(f, 1)), c = grid.P.row(grid.FP(f, 2));
    area += 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  const double spacing = std::sqrt(4.0 * area / (std::sqrt(3.0) * std::max(params.triangles, 2)));
  return isotropic_garment(panels, spacing, kWeldTolerance);
}

VertexSelector pin_box(const Vector3d& lo, const Vector3d& hi) {
  VertexSelector s;
  s.box = Eigen::AlignedBox3d(lo - Vector3d::Constant(kPinSlack), hi + Vector3d::Constant(kPinSlack));
  return s;
}

Scene base_scene(const std::string& name) {
  Scene s;
  s.name = name;
  s.material = *material_preset("cotton-thin");
  return s;
}

SampleScene flag(const SampleParams& params) {
  constexpr double kWidth = 1.0, kHeight = 0.6, kPoleRadius = 0.02, kPoleTop = 2.1, kFlagTop = 2.0;
  // The flag rests in soft vertical waves, as a flag does on a still day: each column-to-column
  // strip is a vertical rectangle turned by kWaveAngle sin(2 pi u / kWavelength) at its middle,
  // so the placement stays exactly isometric. A flat sheet with gravity in its own plane would
  // never leave that plane (a saddle the solver cannot escape).
  constexpr double kWaveAngle = 0.3, kWavelength = 0.25;
  const double h = grid_spacing(kWidth * kHeight, params.triangles);
  const double x0 = kPoleRadius + 0.005, y0 = kFlagTop - kHeight;
  GridPanel panel = flat_panel("flag", divisions(kWidth, h), divisions(kHeight, h), kWidth, kHeight, {x0, y0, 0},
                               Vector3d::UnitX(), Vector3d::UnitY());
  double x = x0, z = 0.0;
  for (int i = 1; i < panel.columns; ++i) {
    const double u0 = panel.pattern(i - 1, 0), u1 = panel.pattern(i, 0);
    const double angle = kWaveAngle * std::sin(std::numbers::pi * (u0 + u1) / kWavelength);
    x += std::cos(angle) * (u1 - u0);
    z += std::sin(angle) * (u1 - u0);
    for (int j = 0; j < panel.rows; ++j) {
      panel.drape(j * panel.columns + i, 0) = x;
      panel.drape(j * panel.columns + i, 2) = z;
    }
  }
  std::vector<GridPanel> panels{panel};
  SampleScene out;
  out.garment = mesh_panels(panels, params);
  out.body = cylinder_mesh({0, 0}, kPoleRadius, 0.0, kPoleTop, 24);
  out.scene = base_scene("flag");
  out.scene.physics.body_contact = false;  // the flag hangs beside the pole, never against it
  out.scene.pins.push_back(pin_box({x0, y0, 0}, {x0, kFlagTop, 0}));
  return out;
}

SampleScene box_cover(const SampleParams& params) {
  const Vector3d box_lo(-0.25, 0.0, -0.20), box_hi(0.25, 0.30, 0.20);
  constexpr double kOffset = 0.005, kHemAboveFloor = 0.02;
  const Vector3d lo = box_lo - Vector3d::Constant(kOffset), hi = box_hi + Vector3d::Constant(kOffset);
  const double W = hi.x() - lo.x(), D = hi.z() - lo.z(), H = hi.y() - kHemAboveFloor;
  const double h = grid_spacing(W * D + 2 * (W + D) * H, params.triangles);
  const int nx = divisions(W, h), nz = divisions(D, h), ny = divisions(H, h);
  const double yb = kHemAboveFloor;
  std::vector<GridPanel> panels{
      flat_panel("top", nx, nz, W, D, {lo.x(), hi.y(), hi.z()}, Vector3d::UnitX(), -Vector3d::UnitZ()),
      flat_panel("front", nx, ny, W, H, {lo.x(), yb, hi.z()}, Vector3d::UnitX(), Vector3d::UnitY()),
      flat_panel("right", nz, ny, D, H, {hi.x(), yb, hi.z()}, -Vector3d::UnitZ(), Vector3d::UnitY()),
      flat_panel("back", nx, ny, W, H, {hi.x(), yb, lo.z()}, -Vector3d::UnitX(), Vector3d::UnitY()),
      flat_panel("left", nz, ny, D, H, {lo.x(), yb, lo.z()}, Vector3d::UnitZ(), Vector3d::UnitY()),
  };
  lay_out_patterns(panels, kLayoutGap);
  SampleScene out;
  out.garment = mesh_panels(panels, params);
  out.body = box_mesh(box_lo, box_hi);
  out.scene = base_scene("box-cover");
  return out;
}

// Body vertices of the torso and legs: per 1 cm slice of height, the vertices from the
// centre line outwards up to the first gap wider than kArmGap in |x| (the arms of an A-pose
// body hang apart from the torso).
std::vector<Vector3d> torso_points(const MatrixX3d& body) {
  constexpr double kSlice = 0.01, kArmGap = 0.03;
  const double cx = 0.5 * (body.col(0).minCoeff() + body.col(0).maxCoeff());
  std::map<long, std::vector<int>> slices;
  for (int v = 0; v < body.rows(); ++v) slices[std::lround(std::floor(body(v, 1) / kSlice))].push_back(v);
  std::vector<Vector3d> out;
  for (auto& [key, ids] : slices) {
    std::sort(ids.begin(), ids.end(), [&](int a, int b) { return std::abs(body(a, 0) - cx) < std::abs(body(b, 0) - cx); });
    double last = std::abs(body(ids.front(), 0) - cx);
    for (int v : ids) {
      const double ax = std::abs(body(v, 0) - cx);
      if (ax - last > kArmGap) break;
      last = ax;
      out.push_back(body.row(v).transpose());
    }
  }
  return out;
}

struct BodyFit {
  EllipseRing waist;
  std::vector<Vector3d> torso;
};

// The natural waist (narrowest torso slice between 55 % and 68 % of body height; standard
// anthropometric range) and an ellipse around the torso there with the given clearance.
BodyFit fit_waist(const MatrixX3d& body, double clearance) {
  BodyFit fit;
  fit.torso = torso_points(body);
  const double y_lo = body.col(1).minCoeff(), height = body.col(1).maxCoeff() - y_lo;
  constexpr double kSlice = 0.01;
  double best = std::numeric_limits<double>::infinity(), y_waist = 0.0;
  for (double y = y_lo + 0.55 * height; y <= y_lo + 0.68 * height; y += kSlice) {
    double half_width = 0.0;
    for (const Vector3d& p : fit.torso)
      if (std::abs(p.y() - y) < kSlice / 2) half_width = std::max(half_width, std::abs(p.x()));
    if (half_width > 0.0 && half_width < best) { best = half_width; y_waist = y; }
  }
  constexpr double kBand = 0.02;
  double xmin = 1e9, xmax = -1e9, zmin = 1e9, zmax = -1e9;
  for (const Vector3d& p : fit.torso)
    if (std::abs(p.y() - y_waist) < kBand) {
      xmin = std::min(xmin, p.x()); xmax = std::max(xmax, p.x());
      zmin = std::min(zmin, p.z()); zmax = std::max(zmax, p.z());
    }
  EllipseRing& w = fit.waist;
  w.cx = 0.5 * (xmin + xmax);
  w.cz = 0.5 * (zmin + zmax);
  w.y = y_waist;
  const double a0 = 0.5 * (xmax - xmin), b0 = 0.5 * (zmax - zmin);
  double s0 = 1.0;
  for (const Vector3d& p : fit.torso)
    if (std::abs(p.y() - y_waist) < kBand) s0 = std::max(s0, std::hypot((p.x() - w.cx) / a0, (p.z() - w.cz) / b0));
  w.a = a0 * s0 + clearance;
  w.b = b0 * s0 + clearance;
  return fit;
}

// Scale of the ring at height `to` (relative to `ring`, growing linearly with distance from
// ring.y) so that every torso point between ring.y (+ a 2 cm band) and `to` is inside the cone
// with the clearance, and at least 1 + min_flare at `to`.
double cone_scale(const BodyFit& fit, const EllipseRing& ring, double to, double clearance, double min_flare) {
  const double length = std::abs(to - ring.y);
  double slope = min_flare / length;
  for (const Vector3d& p : fit.torso) {
    const double d = (to > ring.y) ? p.y() - ring.y : ring.y - p.y();
    if (d < 0.02 || d > length) continue;
    const double s = std::hypot((p.x() - ring.cx) / ring.a, (p.z() - ring.cz) / ring.b) + clearance / std::min(ring.a, ring.b);
    slope = std::max(slope, (s - 1.0) / d);
  }
  return 1.0 + slope * length;
}

EllipseRing scaled(EllipseRing r, double y, double s) {
  r.y = y;
  r.a *= s;
  r.b *= s;
  return r;
}

double ring_perimeter(const EllipseRing& r) {  // Ramanujan's approximation
  return std::numbers::pi * (3 * (r.a + r.b) - std::sqrt((3 * r.a + r.b) * (r.a + 3 * r.b)));
}

double frustum_area(const EllipseRing& r0, const EllipseRing& r1) {
  const double slant = std::hypot(std::abs(r1.y - r0.y), 0.5 * (r1.a + r1.b - r0.a - r0.b));
  return 0.5 * (ring_perimeter(r0) + ring_perimeter(r1)) * slant;
}

// One tier of a fitted garment: the frustum between two rings, cut into a front and a back
// panel at the side seams (phi = 0 and pi).
struct Tier {
  std::string suffix;  // panel names are "front" + suffix and "back" + suffix
  EllipseRing lower, upper;
};

// Front and back panels of every tier, sharing one column layout so that tiers sew to each
// other ring to ring, sized together to about params.triangles; pinned along the ring at pin_y.
SampleScene fitted_garment(const std::string& name, const std::vector<Tier>& tiers, const SampleParams& params, double pin_y) {
  double area = 0.0, perimeter = 0.0;
  for (const Tier& t : tiers) {
    area += frustum_area(t.lower, t.upper);
    perimeter += 0.5 * (ring_perimeter(t.lower) + ring_perimeter(t.upper)) / static_cast<double>(tiers.size());
  }
  int columns = 0;
  std::vector<int> rows(tiers.size());
  double h = grid_spacing(area, params.triangles);
  for (int round = 0; round < kSizingRounds; ++round) {
    columns = 2 * divisions(perimeter / 2, h);  // even: front and back get half each
    int cells = 0;
    for (size_t t = 0; t < tiers.size(); ++t) {
      rows[t] = divisions(tiers[t].upper.y - tiers[t].lower.y, h) + 1;
      cells += columns * (rows[t] - 1);
    }
    h *= std::sqrt(2.0 * cells / params.triangles);
  }
  // Columns follow equal arcs of the first tier's top ring (the waist): rings of one cone are
  // scaled copies, so the arcs are equal on every ring of the garment.
  const std::vector<double> phis = equal_arc_angles(tiers.front().upper, columns, 0.0);
  std::vector<GridPanel> panels;
  for (size_t t = 0; t < tiers.size(); ++t) {
    panels.push_back(cone_panel("front" + tiers[t].suffix, tiers[t].lower, tiers[t].upper, phis, columns / 2, columns, rows[t]));
    panels.push_back(cone_panel("back" + tiers[t].suffix, tiers[t].lower, tiers[t].upper, phis, 0, columns / 2, rows[t]));
  }
  lay_out_patterns(panels, kLayoutGap);
  SampleScene out;
  out.garment = mesh_panels(panels, params);
  out.scene = base_scene(name);
  const double far = 10.0;
  out.scene.pins.push_back(pin_box({-far, pin_y, -far}, {far, pin_y, far}));
  return out;
}

SampleScene skirt(const SampleParams& params, const MatrixX3d& body) {
  const BodyFit fit = fit_waist(body, params.clearance);
  const EllipseRing& waist = fit.waist;
  const double y_hem = waist.y - params.waist_to_hem;
  const EllipseRing hem = scaled(waist, y_hem, cone_scale(fit, waist, y_hem, params.clearance, params.min_flare));
  return fitted_garment("skirt", {{"", hem, waist}}, params, waist.y);
}

SampleScene dress(const SampleParams& params, const MatrixX3d& body) {
  const BodyFit fit = fit_waist(body, params.clearance);
  const EllipseRing& waist = fit.waist;
  const double y_hem = waist.y - params.dress_waist_to_hem, y_top = waist.y + params.bodice_height;
  const EllipseRing hem = scaled(waist, y_hem, cone_scale(fit, waist, y_hem, params.clearance, params.min_flare));
  const EllipseRing top = scaled(waist, y_top, cone_scale(fit, waist, y_top, params.clearance, 0.0));
  return fitted_garment("dress", {{"-skirt", hem, waist}, {"-bodice", waist, top}}, params, y_top);
}

} // namespace

std::vector<std::string> sample_names() { return {"flag", "skirt", "box-cover", "dress"}; }

bool sample_needs_body(const std::string& name) { return name == "skirt" || name == "dress"; }

SampleScene make_sample(const std::string& name, const SampleParams& params, const MatrixX3d* body_V) {
  if (sample_needs_body(name) && (body_V == nullptr || body_V->rows() == 0))
    throw ArgumentError("make_sample: sample '" + name + "' needs a body mesh");
  if (name == "flag") return flag(params);
  if (name == "box-cover") return box_cover(params);
  if (name == "skirt") return skirt(params, *body_V);
  if (name == "dress") return dress(params, *body_V);
  throw ArgumentError("make_sample: unknown sample '" + name + "'");
}

} // namespace foldsketch
