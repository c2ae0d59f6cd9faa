#include "formats/dxf_aama.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include <Eigen/Geometry>

#include "formats/text_numbers.h"

namespace foldsketch {
namespace {

constexpr double kMm = 1000.0;
// AAMA / ASTM D6673 layers.
constexpr const char* kBoundary = "1";
constexpr const char* kTurnPoints = "2";
constexpr const char* kCurvePoints = "3";
constexpr const char* kNotches = "4";
constexpr const char* kGrain = "7";
constexpr const char* kInternalLines = "8";
constexpr const char* kCutOuts = "11";
constexpr const char* kDrillHoles = "13";
constexpr const char* kSewLines = "14";
// Every layer of the convention we write (declared in the LAYER table) and layer 0, which DXF
// readers expect to exist; nothing is drawn on it.
constexpr const char* kLayers[] = {"0", "1", "2", "3", "4", "6", "7", "8", "11", "13", "14", "15"};
// A cut-line vertex where the outline turns by more than this is a turn point, else a curve
// point. 25 degrees, as boundary_corners() (lib/garment/boundary_runs.h).
constexpr double kTurnAngle = 25.0 * std::numbers::pi / 180.0;
constexpr double kTextHeight = 4.0;   // [mm]
constexpr double kLineSpacing = 6.0;  // [mm]

// Millimetres to 0.1 um: far finer than any cutter, short enough to read.
std::string number(double mm) { return format_fixed(mm, 4); }

class DxfText {
public:
  void group(int code, const std::string& value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%3d\n", code);
    out_ += buffer;
    out_ += value;
    out_ += '\n';
  }
  void group(int code, int value) { group(code, std::to_string(value)); }
  void point(const Vector2d& p_mm, int base = 10) {
    group(base, number(p_mm.x()));
    group(base + 10, number(p_mm.y()));
    group(base + 20, "0");
  }
  void entity(const char* type, const char* layer) {
    group(0, type);
    group(8, layer);
  }
  void begin_section(const char* name) {
    group(0, "SECTION");
    group(2, name);
  }
  void end_section() { group(0, "ENDSEC"); }
  // A table of `count` entries, each opened by table_entry(type, name) with type the table's
  // name; end_table() closes it.
  void begin_table(const char* name, int count) {
    group(0, "TABLE");
    group(2, name);
    group(70, count);
  }
  void table_entry(const char* type, const char* name) {
    group(0, type);
    group(2, name);
    group(70, 0);  // no flags
  }
  void end_table() { group(0, "ENDTAB"); }
  const std::string& str() const { return out_; }

private:
  std::string out_;
};

Vector2d mm(const Vector2d& p) { return p * kMm; }

void polyline(DxfText& dxf, const Loop2& loop, const char* layer, bool closed) {
  dxf.entity("POLYLINE", layer);
  dxf.group(66, 1);
  dxf.point(Vector2d::Zero());
  dxf.group(70, closed ? 1 : 0);
  for (const Vector2d& p : loop) {
    dxf.entity("VERTEX", layer);
    dxf.point(mm(p));
  }
  dxf.entity("SEQEND", layer);
}

void line(DxfText& dxf, const Vector2d& a, const Vector2d& b, const char* layer) {
  dxf.entity("LINE", layer);
  dxf.point(mm(a), 10);
  dxf.point(mm(b), 11);
}

void text(DxfText& dxf, const Vector2d& at_mm, const std::string& s, const char* layer) {
  dxf.entity("TEXT", layer);
  dxf.point(at_mm);
  dxf.group(40, number(kTextHeight));
  dxf.group(1, ascii_text(s));
}

// Turn points and curve points of a closed loop.
void loop_points(DxfText& dxf, const Loop2& loop) {
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const Vector2d a = loop[i] - loop[(i + n - 1) % n], b = loop[(i + 1) % n] - loop[i];
    const double turn = std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
    dxf.entity("POINT", turn > kTurnAngle ? kTurnPoints : kCurvePoints);
    dxf.point(mm(loop[i]));
  }
}

void piece_block(DxfText& dxf, const std::vector<CuttingPiece>& pieces, const std::vector<std::string>& names, int i,
                 const PatternText& t) {
  const CuttingPiece& piece = pieces[i];
  dxf.group(0, "BLOCK");
  dxf.group(8, kBoundary);
  dxf.group(2, names[i]);
  dxf.group(70, 0);
  dxf.point(Vector2d::Zero());
  dxf.group(3, names[i]);
  polyline(dxf, piece.cut.outer, kBoundary, true);
  loop_points(dxf, piece.cut.outer);
  for (const Loop2& hole : piece.cut.holes) {
    polyline(dxf, hole, kCutOuts, true);
    loop_points(dxf, hole);
  }
  if (t.seam_allowance > 0.0)
    for (const Loop2& sew : piece.sew) polyline(dxf, sew, kSewLines, true);
  for (const Notch& notch : piece.notches) line(dxf, notch.at, notch.at + notch.depth * notch.inward, kNotches);
  line(dxf, piece.grain_from, piece.grain_to, kGrain);
  for (const auto& internal : piece.internal_lines) polyline(dxf, internal, kInternalLines, false);
  for (const Vector2d& hole : piece.drill_holes) {
    dxf.entity("POINT", kDrillHoles);
    dxf.point(mm(hole));
  }
  // Piece texts beside the grain line, top down.
  Vector2d at = mm(piece.grain_to) + Vector2d(kTextHeight, -kTextHeight);
  const auto say = [&](const std::string& s) {
    text(dxf, at, s, kBoundary);
    at.y() -= kLineSpacing;
  };
  say("Piece Name: " + names[i]);
  say("Size: " + t.size);
  say("Quantity: " + std::to_string(piece.quantity));
  say("Category: " + t.category);
  say("Annotation: " + cutting_instruction(pieces, names, i) + "; seam allowance " + number(t.seam_allowance * kMm) + " mm");
  say("Material: " + t.material);
  dxf.group(0, "ENDBLK");
  dxf.group(8, kBoundary);
}

void header(DxfText& dxf, const Eigen::AlignedBox2d& extent_mm) {
  dxf.begin_section("HEADER");
  dxf.group(9, "$ACADVER");
  dxf.group(1, "AC1009");
  dxf.group(9, "$INSBASE");
  dxf.point(Vector2d::Zero());
  dxf.group(9, "$EXTMIN");
  dxf.point(extent_mm.min());
  dxf.group(9, "$EXTMAX");
  dxf.point(extent_mm.max());
  dxf.group(9, "$LUNITS");
  dxf.group(70, 2);  // decimal
  dxf.end_section();

  dxf.begin_section("TABLES");
  dxf.begin_table("LTYPE", 1);
  dxf.table_entry("LTYPE", "CONTINUOUS");
  dxf.group(3, "Solid line");
  dxf.group(72, 65);
  dxf.group(73, 0);
  dxf.group(40, "0.0");
  dxf.end_table();
  dxf.begin_table("LAYER", static_cast<int>(std::size(kLayers)));
  for (const char* layer : kLayers) {
    dxf.table_entry("LAYER", layer);
    dxf.group(62, 7);
    dxf.group(6, "CONTINUOUS");
  }
  dxf.end_table();
  dxf.begin_table("STYLE", 1);
  dxf.table_entry("STYLE", "STANDARD");
  dxf.group(40, "0.0");
  dxf.group(41, "1.0");
  dxf.group(50, "0.0");
  dxf.group(71, 0);
  dxf.group(42, number(kTextHeight));
  dxf.group(3, "txt");
  dxf.group(4, "");
  dxf.end_table();
  dxf.end_section();
}

} // namespace

std::string ascii_text(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f) out += static_cast<char>(c);
    else if (c < 0x80 || c >= 0xc0) out += '?';  // a control character, or the lead byte of a UTF-8 sequence
  }
  return out;
}

std::vector<std::string> piece_block_names(const std::vector<CuttingPiece>& pieces) {
  std::vector<std::string> names;
  std::set<std::string> used;
  for (const CuttingPiece& piece : pieces) {
    std::string base;
    for (unsigned char c : piece.name) {
      if (std::isalnum(c) && c < 0x80) base += static_cast<char>(std::toupper(c));
      else if (c == '-' || c == '_') base += static_cast<char>(c);
      else if (c < 0x80 || c >= 0xc0) base += '_';
    }
    if (base.empty()) base = "PIECE";
    std::string name = base;
    for (int k = 2; used.count(name); ++k) name = base + "_" + std::to_string(k);
    used.insert(name);
    names.push_back(name);
  }
  return names;
}

std::string cutting_instruction(const std::vector<CuttingPiece>& pieces, const std::vector<std::string>& names, int i) {
  const CuttingPiece& piece = pieces[i];
  if (piece.quantity == 2)
    return piece.partner_match == PanelMatch::Mirror ? "cut pair (" + piece.name + " and its mirror image " + piece.merged + ")"
                                                     : "cut 2 (" + piece.name + " and " + piece.merged + ")";
  if (!piece.partner) return "cut " + std::to_string(piece.quantity);
  const std::string& other = names[*piece.partner];
  return piece.partner_match == PanelMatch::Mirror ? "cut 1 (pair with " + other + ": mirror image)"
                                                   : "cut 1 (same as " + other + ")";
}

std::string aama_dxf(const std::vector<CuttingPiece>& pieces, const std::vector<Vector2d>& insert_at,
                     const PatternText& t, const DxfOptions& options) {
  const std::vector<std::string> names = piece_block_names(pieces);
  Eigen::AlignedBox2d extent;
  for (size_t i = 0; i < pieces.size(); ++i)
    for (const Vector2d& p : pieces[i].cut.outer) extent.extend(mm(p + insert_at[i]));
  if (extent.isEmpty()) extent.extend(Vector2d::Zero());

  DxfText dxf;
  header(dxf, extent);
  dxf.begin_section("BLOCKS");
  for (size_t i = 0; i < pieces.size(); ++i) piece_block(dxf, pieces, names, static_cast<int>(i), t);
  dxf.end_section();

  dxf.begin_section("ENTITIES");
  for (size_t i = 0; i < pieces.size(); ++i) {
    dxf.entity("INSERT", kBoundary);
    dxf.group(2, names[i]);
    dxf.point(mm(insert_at[i]));
  }
  if (!options.strict) {
    // Style system text, under the drawing.
    Vector2d at(extent.min().x(), extent.min().y() - 2.0 * kLineSpacing);
    for (const std::string& s : {"Style Name: " + t.style_name, "Creation Date: " + t.creation_date,
                                 "Author: " + t.author, "Sample Size: " + t.size, std::string("Units: METRIC")}) {
      text(dxf, at, s, kBoundary);
      at.y() -= kLineSpacing;
    }
  }
  dxf.end_section();
  dxf.group(0, "EOF");
  return dxf.str();
}

} // namespace foldsketch
