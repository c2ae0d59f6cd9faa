#include "formats/dxf_aama.h"

#include <gtest/gtest.h>

namespace foldsketch {
namespace {

CuttingPiece square_piece(const std::string& name) {
  CuttingPiece piece;
  piece.name = name;
  piece.sew = {{{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}}};
  piece.cut = seam_allowance(piece.sew[0], {});
  piece.grain_from = {0.05, 0.02};
  piece.grain_to = {0.05, 0.08};
  piece.notches.push_back({{0.11, 0.05}, {-1, 0}, 0.006});
  piece.internal_lines.push_back({{0.03, 0.0}, {0.03, 0.1}});  // a pleat fold line
  piece.drill_holes.push_back({0.03, 0.09});
  return piece;
}

bool has(const std::string& text, const std::string& needle) { return text.find(needle) != std::string::npos; }

TEST(DxfAama, EveryKindOfMarkGoesOnItsLayer) {
  const std::vector<CuttingPiece> pieces{square_piece("front")};
  PatternText text;
  text.seam_allowance = 0.01;
  const std::string dxf = aama_dxf(pieces, {Vector2d::Zero()}, text);
  EXPECT_TRUE(has(dxf, "  0\nPOLYLINE\n  8\n1\n"));   // cut line
  EXPECT_TRUE(has(dxf, "  0\nPOINT\n  8\n2\n"));      // its four mitred corners are turn points
  EXPECT_TRUE(has(dxf, "  0\nLINE\n  8\n4\n 10\n110\n 20\n50\n"));  // the notch, in mm
  EXPECT_TRUE(has(dxf, "  0\nLINE\n  8\n7\n"));       // grain line
  EXPECT_TRUE(has(dxf, "  0\nPOLYLINE\n  8\n8\n"));   // internal line
  EXPECT_TRUE(has(dxf, "  0\nPOINT\n  8\n13\n 10\n30\n 20\n90\n"));  // drill hole
  EXPECT_TRUE(has(dxf, "  0\nPOLYLINE\n  8\n14\n"));  // sew line
  EXPECT_FALSE(has(dxf, "\n  8\n0\n"));               // nothing on layer 0
  EXPECT_TRUE(has(dxf, "\n  1\nPiece Name: FRONT\n"));
  EXPECT_TRUE(has(dxf, "\n  1\nUnits: METRIC\n"));
  EXPECT_TRUE(has(dxf, "$ACADVER\n  1\nAC1009\n"));
  const std::string strict = aama_dxf(pieces, {Vector2d::Zero()}, text, {.strict = true});
  EXPECT_FALSE(has(strict, "Units: METRIC"));
  EXPECT_TRUE(has(strict, "\n  1\nPiece Name: FRONT\n"));
}

TEST(DxfAama, NoAllowanceMeansNoSewLine) {
  const std::vector<CuttingPiece> pieces{square_piece("front")};
  EXPECT_FALSE(has(aama_dxf(pieces, {Vector2d::Zero()}, PatternText{}), "POLYLINE\n  8\n14\n"));
}

TEST(DxfAama, NamesAndTextsAreAscii) {
  EXPECT_EQ(ascii_text("Armel \xc3\x84rmel \xe2\x82\xac 5\t"), "Armel ?rmel ? 5?");
  const std::vector<CuttingPiece> pieces{square_piece("Front"), square_piece("front"), square_piece(""), square_piece("a b")};
  EXPECT_EQ(piece_block_names(pieces), (std::vector<std::string>{"FRONT", "FRONT_2", "PIECE", "A_B"}));
}

} // namespace
} // namespace foldsketch
