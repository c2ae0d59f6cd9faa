#include "pattern/seam_allowance.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.h"

namespace foldsketch {
namespace {

constexpr double kMm = 0.001;
constexpr double kD = 10 * kMm;           // allowance
constexpr double kRoundoff = 1e-9;        // [m]

Loop2 rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Loop2 reversed(Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

// Every cut vertex lies between d and mitre_limit * d from the sew outline (outer and holes),
// the cut loops are simple and correctly oriented, and every sew vertex is at least d inside.
void expect_valid_offset(const Loop2& outer, const std::vector<Loop2>& holes, const CutOutline& cut,
                         const AllowanceParams& params = {}) {
  const auto distance_to_sew = [&](const Vector2d& p) {
    double d = distance_to_loop(p, outer);
    for (const Loop2& h : holes) d = std::min(d, distance_to_loop(p, h));
    return d;
  };
  ASSERT_GE(cut.outer.size(), 3u);
  EXPECT_TRUE(is_simple(cut.outer));
  EXPECT_GT(signed_area(cut.outer), 0.0);
  for (const Loop2& h : cut.holes) {
    EXPECT_TRUE(is_simple(h));
    EXPECT_LT(signed_area(h), 0.0);
  }
  for (const Loop2* loop : [&] {
         std::vector<const Loop2*> all{&cut.outer};
         for (const Loop2& h : cut.holes) all.push_back(&h);
         return all;
       }()) {
    for (const Vector2d& p : *loop) {
      const double d = distance_to_sew(p);
      EXPECT_GE(d, params.allowance - kRoundoff) << p.transpose();
      EXPECT_LE(d, std::hypot(params.mitre_limit, 1.0) * params.allowance + kRoundoff) << p.transpose();
    }
  }
  for (const Vector2d& p : outer) {
    double d = distance_to_loop(p, cut.outer);
    for (const Loop2& h : cut.holes) d = std::min(d, distance_to_loop(p, h));
    EXPECT_GE(d, params.allowance - kRoundoff);
  }
}

TEST(SeamAllowance, ZeroAllowanceReturnsTheOutline) {
  const Loop2 square = rectangle(0, 0, 0.1, 0.1);
  const CutOutline cut = seam_allowance(square, {}, {.allowance = 0.0});
  EXPECT_EQ(cut.outer, square);
  EXPECT_TRUE(cut.holes.empty());
}

TEST(SeamAllowance, SquareCornersAreMitred) {
  const Loop2 square = rectangle(0, 0, 0.1, 0.1);
  const CutOutline cut = seam_allowance(square, {});
  ASSERT_EQ(cut.outer.size(), 4u);  // collinear vertices of the union removed
  EXPECT_NEAR(signed_area(cut.outer), 0.12 * 0.12, 1e-15);
  for (const Vector2d& p : cut.outer)
    for (double x : {p.x(), p.y()}) EXPECT_TRUE(x == -0.01 || std::abs(x - 0.11) < 1e-15) << p.transpose();
  expect_valid_offset(square, {}, cut);
}

TEST(SeamAllowance, ConcaveCornerMeetsInside) {
  // An L: the reflex corner at (0.05, 0.05) offsets to the point (0.06, 0.06).
  const Loop2 l{{0, 0}, {0.1, 0}, {0.1, 0.05}, {0.05, 0.05}, {0.05, 0.1}, {0, 0.1}};
  const CutOutline cut = seam_allowance(l, {});
  expect_valid_offset(l, {}, cut);
  ASSERT_EQ(cut.outer.size(), 6u);
  bool found = false;
  for (const Vector2d& p : cut.outer) found = found || (p - Vector2d(0.06, 0.06)).norm() < 1e-15;
  EXPECT_TRUE(found);
  EXPECT_NEAR(signed_area(cut.outer), 0.12 * 0.12 - 0.05 * 0.05, 1e-15);
}

TEST(SeamAllowance, EdgesFarShorterThanTheAllowance) {
  // A step of 0.3 mm and a 0.5 mm tooth on an edge: offsetting edge by edge would cross itself.
  const Loop2 outline{{0, 0},       {0.05, 0},      {0.05, 0.0003}, {0.1, 0.0003}, {0.1, 0.05},
                      {0.0602, 0.05}, {0.0602, 0.0505}, {0.0597, 0.0505}, {0.0597, 0.05}, {0, 0.05}};
  const CutOutline cut = seam_allowance(outline, {});
  expect_valid_offset(outline, {}, cut);
}

TEST(SeamAllowance, NarrowStrip) {
  // 5 mm wide: narrower than the allowance on either side.
  const Loop2 strip = rectangle(0, 0, 0.2, 0.005);
  const CutOutline cut = seam_allowance(strip, {});
  expect_valid_offset(strip, {}, cut);
  EXPECT_NEAR(signed_area(cut.outer), 0.22 * 0.025, 1e-15);
  // A strip bent into a U, its arms 3 mm apart: the allowance fills the gap and the cut line
  // stays one simple loop.
  const Loop2 u{{0, 0}, {0.013, 0}, {0.013, 0.1}, {0.008, 0.1}, {0.008, 0.005}, {0.005, 0.005}, {0.005, 0.1}, {0, 0.1}};
  const CutOutline cut_u = seam_allowance(u, {});
  expect_valid_offset(u, {}, cut_u);
  EXPECT_TRUE(cut_u.holes.empty());
}

TEST(SeamAllowance, HolesShrinkAndVanish) {
  const Loop2 square = rectangle(0, 0, 0.1, 0.1);
  const Loop2 hole = reversed(rectangle(0.03, 0.03, 0.07, 0.07));  // 40 mm: becomes 20 mm
  const CutOutline cut = seam_allowance(square, {hole});
  expect_valid_offset(square, {hole}, cut);
  ASSERT_EQ(cut.holes.size(), 1u);
  EXPECT_NEAR(signed_area(cut.holes[0]), -0.02 * 0.02, 1e-15);
  const Loop2 small = reversed(rectangle(0.04, 0.04, 0.055, 0.055));  // 15 mm: filled by the allowance
  const CutOutline filled = seam_allowance(square, {small});
  EXPECT_TRUE(filled.holes.empty());
  expect_valid_offset(square, {small}, filled);
}

TEST(SeamAllowance, SharpCornersAreSquaredAtTheMitreLimit) {
  // A 10-degree spike: its mitre would reach 11.5 allowances out.
  const double half = 5.0 * std::numbers::pi / 180.0;
  const Loop2 triangle{{0, 0}, {0.1, -0.1 * std::tan(half)}, {0.1, 0.1 * std::tan(half)}};
  const CutOutline cut = seam_allowance(triangle, {});
  expect_valid_offset(triangle, {}, cut);
  // Two corners of the cut line, on the line square to the tip's bisector 2 allowances out.
  int near_tip = 0;
  for (const Vector2d& p : cut.outer) near_tip += p.x() < 0 ? 1 : 0;
  EXPECT_EQ(near_tip, 2);
  for (const Vector2d& p : cut.outer) {
    if (p.x() < 0) {
      EXPECT_NEAR(p.x(), -2.0 * kD, 1e-12);
    }
  }
}

TEST(SeamAllowance, DenseCurveIsFastAndExact) {
  // A circle of 2000 vertices, as a garment's curved edge at high resolution.
  const int n = 2000;
  Loop2 circle;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    circle.emplace_back(0.3 * std::cos(a), 0.3 * std::sin(a));
  }
  const auto start = std::chrono::steady_clock::now();
  const CutOutline cut = seam_allowance(circle, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_valid_offset(circle, {}, cut);
  EXPECT_LT(seconds, 20.0) << "a generous bound: the union should take well under a second";
  std::printf("2000-vertex circle: %zu cut vertices in %.3f s\n", cut.outer.size(), seconds);
}

TEST(SeamAllowance, RefusesBadInput) {
  EXPECT_THROW(seam_allowance({{0, 0}, {1, 0}}, {}), ArgumentError);
  EXPECT_THROW(seam_allowance({{0, 0}, {1, 0}, {NAN, 1}}, {}), ArgumentError);
  EXPECT_THROW(seam_allowance(rectangle(0, 0, 1, 1), {}, {.allowance = -1.0}), ArgumentError);
  EXPECT_THROW(seam_allowance(reversed(rectangle(0, 0, 1, 1)), {}), ArgumentError);      // clockwise
  EXPECT_THROW(seam_allowance({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, {}), ArgumentError);     // crossing
}

} // namespace
} // namespace foldsketch
