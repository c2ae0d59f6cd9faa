// Cutting patterns as DXF in the AAMA / ASTM D6673 convention (see dxf-aama.md): one BLOCK per
// piece, INSERTed once in ENTITIES; numeric layers; R12 (AC1009); millimetres, y up; ASCII.
#pragma once

#include <string>
#include <vector>

#include "pattern/cutting_pieces.h"

namespace foldsketch {

// What the style and piece texts say.
struct PatternText {
  std::string style_name = "foldsketch";
  std::string author = "foldsketch";
  std::string creation_date;         // e.g. "2026-11-24 09:30"
  std::string size = "base";          // the sample size of the style
  std::string material = "fabric";
  std::string category = "SELF";      // AAMA piece category (self fabric, lining, interfacing...)
  double seam_allowance = 0.0;        // [m], stated in each piece's annotation
};

struct DxfOptions {
  // Strict: ENTITIES holds nothing but the INSERTs of the piece blocks (no style text), for
  // importers that reject anything else.
  bool strict = false;
};

// Block names for the pieces: the panel names in upper-case ASCII letters, digits, '_' and '-'
// (DXF names are case-insensitive), made unique with a _2, _3... suffix.
std::vector<std::string> piece_block_names(const std::vector<CuttingPiece>& pieces);

// Printable ASCII only: other characters become '?', one per UTF-8 character.
std::string ascii_text(const std::string& text);

// One-line quantity and pairing of a piece, e.g. "cut 1 (pair with BACK: mirror image)".
std::string cutting_instruction(const std::vector<CuttingPiece>& pieces, const std::vector<std::string>& names, int i);

// The DXF text. Piece i is drawn in its own pattern coordinates inside its block and inserted at
// insert_at[i] [m], so that the pieces do not overlap on the drawing.
std::string aama_dxf(const std::vector<CuttingPiece>& pieces, const std::vector<Vector2d>& insert_at,
                     const PatternText& text, const DxfOptions& options = {});

} // namespace foldsketch
