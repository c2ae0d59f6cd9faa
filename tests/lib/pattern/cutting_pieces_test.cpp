#include "pattern/cutting_pieces.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "formats/garment_io.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

constexpr double kD = 0.010;  // the default allowance [m]

TEST(CuttingPieces, SeamEndsAreNotchedOnTheCutLine) {
  const Garment g = test::two_sewn_squares();  // one seam of a single edge
  const CuttingLayout layout = cutting_pieces(g);
  ASSERT_EQ(layout.pieces.size(), 2u);
  ASSERT_EQ(layout.seams.size(), 1u);
  for (const CuttingPiece& piece : layout.pieces) {
    ASSERT_EQ(piece.notches.size(), 2u) << piece.name;  // both ends; no middle vertex to notch
    for (const Notch& n : piece.notches) {
      EXPECT_LT(distance_to_loop(n.at, piece.cut.outer), 1e-12) << piece.name;
      EXPECT_NEAR(distance_to_loop(n.at, piece.sew.front()), kD, 1e-12);
      EXPECT_DOUBLE_EQ(n.depth, 0.006);
      // Square to the seam: the seam is the line x = 1 in both patterns' frames (left: x = 1 of
      // [0,1]; right: x = 0 of its own square, wherever it sits).
      EXPECT_NEAR(std::abs(n.inward.x()), 1.0, 1e-12);
    }
  }
  // Both squares are the same piece.
  ASSERT_TRUE(layout.pieces[0].partner);
  EXPECT_EQ(*layout.pieces[0].partner, 1);
  EXPECT_EQ(layout.pieces[0].partner_match, PanelMatch::Copy);
}

TEST(CuttingPieces, LongSeamsGetABalanceNotchAtTheSameDrapePointOnBothSides) {
  const Garment g = read_garment(test::source_path("samples/skirt/garment.obj"));
  const CuttingLayout layout = cutting_pieces(g);
  ASSERT_EQ(layout.seams.size(), 2u);  // the side seams, 567 mm each
  for (const CuttingPiece& piece : layout.pieces) EXPECT_EQ(piece.notches.size(), 6u) << piece.name;
  // The middle notches of side a and side b sit on one drape vertex.
  for (const Seam& seam : layout.seams) {
    const VectorXi drape = pattern_to_drape(g);
    const int m = static_cast<int>(seam.a.vertices.size());
    const double half = 0.5 * pattern_length(g.P, seam.a.vertices);
    int k = 1;
    for (double walked = 0.0; k < m; ++k) {
      walked += (g.P.row(seam.a.vertices[k]) - g.P.row(seam.a.vertices[k - 1])).norm();
      if (walked >= half) break;
    }
    EXPECT_EQ(drape(seam.a.vertices[k]), drape(seam.b.vertices[k]));
    const Vector2d mid_a = g.P.row(seam.a.vertices[k]).transpose(), mid_b = g.P.row(seam.b.vertices[k]).transpose();
    const auto has_notch_near = [&](int panel, const Vector2d& p) {
      for (const Notch& n : layout.pieces[panel].notches)
        if (std::abs((n.at - p).norm() - kD) < 1e-3) return true;
      return false;
    };
    EXPECT_TRUE(has_notch_near(seam.a.panel, mid_a));
    EXPECT_TRUE(has_notch_near(seam.b.panel, mid_b));
  }
}

TEST(CuttingPieces, GrainLineRunsAlongPatternYInsideThePiece) {
  const Garment g = test::square_panel(4, 0.5);
  const CuttingPiece piece = cutting_pieces(g).pieces[0];
  EXPECT_DOUBLE_EQ(piece.grain_from.x(), piece.grain_to.x());
  EXPECT_GT(piece.grain_to.y(), piece.grain_from.y());
  EXPECT_NEAR(piece.grain_to.y() - piece.grain_from.y(), 0.7 * (0.5 + 2 * kD), 1e-9);
  EXPECT_TRUE(piece.notches.empty());
  EXPECT_FALSE(piece.partner);
}

TEST(CuttingPieces, HoleIsAnInternalCutOutAndASewLine) {
  MatrixX2d outer(4, 2), hole(4, 2);
  outer << 0, 0, 0.2, 0, 0.2, 0.2, 0, 0.2;
  hole << 0.05, 0.05, 0.05, 0.15, 0.15, 0.15, 0.15, 0.05;
  const CuttingPiece piece = cutting_pieces(test::polygon_panel("window", outer, 0.02, {hole})).pieces[0];
  ASSERT_EQ(piece.sew.size(), 2u);
  EXPECT_GT(signed_area(piece.sew[0]), 0.0);
  EXPECT_LT(signed_area(piece.sew[1]), 0.0);
  ASSERT_EQ(piece.cut.holes.size(), 1u);
  EXPECT_NEAR(signed_area(piece.cut.holes[0]), -0.08 * 0.08, 1e-12);
}

TEST(CuttingPieces, ClockwisePatternsAreTurnedAround) {
  Garment g = test::square_panel(3, 0.3);
  g.F.col(1).swap(g.F.col(2));
  g.FP.col(1).swap(g.FP.col(2));
  const CuttingPiece piece = cutting_pieces(g).pieces[0];
  EXPECT_GT(signed_area(piece.sew.front()), 0.0);
  EXPECT_NEAR(signed_area(piece.cut.outer), (0.3 + 2 * kD) * (0.3 + 2 * kD), 1e-12);
}

Loop2 shifted(const Loop2& loop, int by) {
  Loop2 out;
  for (size_t i = 0; i < loop.size(); ++i) out.push_back(loop[(i + static_cast<size_t>(by)) % loop.size()]);
  return out;
}

TEST(CongruentPanels, CopiesMirrorImagesAndStrangers) {
  // An asymmetric quadrilateral; a rotated, moved copy; its mirror image; and a slightly different one.
  const Loop2 a{{0, 0}, {0.4, 0}, {0.35, 0.6}, {0.05, 0.5}};
  const Eigen::Rotation2Dd r(0.7);
  Loop2 copy, mirror, other = a;
  for (const Vector2d& p : a) copy.push_back(r * p + Vector2d(2, 1));
  for (auto it = a.rbegin(); it != a.rend(); ++it) mirror.push_back(Vector2d(5 - it->x(), it->y()));
  other[2].y() += 0.003;
  const auto pairs = congruent_panels({a, shifted(copy, 1), other, shifted(mirror, 3)}, 1e-4);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].a, 0);
  EXPECT_EQ(pairs[0].b, 1);
  EXPECT_EQ(pairs[0].match, PanelMatch::Copy);
  const auto mirrored = congruent_panels({a, other, shifted(mirror, 2)}, 1e-4);
  ASSERT_EQ(mirrored.size(), 1u);
  EXPECT_EQ(mirrored[0].b, 2);
  EXPECT_EQ(mirrored[0].match, PanelMatch::Mirror);
  EXPECT_LT(mirrored[0].rms, 1e-12);
  EXPECT_TRUE(congruent_panels({a, other}, 1e-4).empty());
}

} // namespace
} // namespace foldsketch
