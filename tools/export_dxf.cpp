// export-dxf: cutting patterns a cutting room can use. AAMA/ASTM-style DXF, 1:1 SVG, PNG
// preview, and a seam report (both sides of every seam) on standard output.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>

#include "cli.h"
#include "core/error.h"
#include "formats/atomic_file.h"
#include "formats/dxf_aama.h"
#include "formats/garment_io.h"
#include "formats/json_writer.h"
#include "formats/pattern_sheet.h"
#include "formats/scene_xml.h"
#include "pattern/cutting_pieces.h"

namespace foldsketch {
namespace {

constexpr double kMm = 1000.0;

std::string fmt(const char* format, auto... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

// "YYYY-MM-DD HH:MM UTC" of SOURCE_DATE_EPOCH when set (reproducible output), else of now.
std::string creation_date() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) t = static_cast<std::time_t>(std::strtoll(epoch, nullptr, 10));
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &utc);
  return buffer;
}

// Millimetres for a table: no "-0.000" for a difference that rounds to zero.
double shown(double mm) { return std::abs(mm) < 5e-4 ? 0.0 : mm; }

// Every output's folder must exist before the first file is written, so that a typo in the last
// path does not leave the first outputs of a run beside nothing.
void check_output_folders(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (path.empty() || path == "-") continue;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
      throw InputError(path, 0, "cannot write here: folder '" + folder.string() + "' does not exist");
  }
}

struct SeamRow {
  int panel_a, panel_b;
  double length_a, length_b;  // [m]
  bool closed;
};

// Distance range of a piece's cut vertices from its sew line [m]: the allowance, checked.
std::pair<double, double> allowance_range(const CuttingPiece& piece) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Loop2* loop : piece.cut.loops())
    for (const Vector2d& p : *loop) {
      double d = std::numeric_limits<double>::infinity();
      for (const Loop2& sew : piece.sew) d = std::min(d, distance_to_loop(p, sew));
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  return {lo, hi};
}

} // namespace
} // namespace foldsketch

int main(int argc, char** argv) {
  using namespace foldsketch;
  CLI::App app{"Reads sewing patterns (a garment OBJ: vt = pattern in metres, one group per panel; or a scene.xml,\n"
               "which also names the material) and writes the cutting patterns: a DXF in the AAMA/ASTM D6673\n"
               "convention (R12, millimetres, one block per piece; see formats/dxf-aama.md), optionally a 1:1 SVG\n"
               "(millimetres) and a PNG preview. Each panel is a piece: cut line with seam allowance, dashed sew\n"
               "line, notches at seam ends and middles, grain line along the warp (pattern y), pieces cut from\n"
               "the same pattern flagged. Prints a seam report (both sides of every seam, mm) on standard output\n"
               "(standard error when the DXF goes to standard output).",
               "export-dxf"};
  std::string input, output, svg_path, png_path, style, author = "foldsketch", size = "base", material, category = "SELF";
  double allowance_mm = 10.0, png_scale = 2.0, mitre_limit = 2.0;
  bool strict = false, as_json = false, merge_pairs = false;
  app.add_option("patterns", input, "garment OBJ or scene XML")->required();
  app.add_option("-o,--output", output, "DXF to write ('-' = standard output)")->required();
  app.add_option("--svg", svg_path, "also write a 1:1 SVG (mm) of the pieces");
  app.add_option("--png", png_path, "also write a PNG preview of the SVG drawing");
  app.add_option("--png-scale", png_scale, "PNG pixels per millimetre")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seam-allowance", allowance_mm, "seam allowance [mm]; 0 cuts on the sew line")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--mitre-limit", mitre_limit, "allowance corners are mitred up to this many allowances out, squared beyond")
      ->capture_default_str()->check(CLI::Range(1.0, 100.0));
  app.add_flag("--strict", strict, "DXF ENTITIES hold only the piece INSERTs (no style text)");
  app.add_flag("--merge-pairs", merge_pairs,
               "one piece for each pair of congruent panels: quantity 2, 'cut 2' (copies) or 'cut pair' (mirror images)");
  app.add_option("--style", style, "style name (default: the scene's name, or the garment file's)");
  app.add_option("--author", author, "author text")->capture_default_str();
  app.add_option("--size", size, "sample size text")->capture_default_str();
  app.add_option("--material", material, "material text (default: the scene's material, or 'fabric')");
  app.add_option("--category", category, "AAMA piece category")->capture_default_str();
  app.add_flag("--json", as_json, "print the report as one line of JSON");
  return run_tool(app, argc, argv, [&] {
    const auto start = std::chrono::steady_clock::now();
    std::string garment_path = input;
    PatternText text;
    text.material = "fabric";
    text.style_name = std::filesystem::path(input).stem().string();
    if (std::filesystem::path(input).extension() == ".xml") {
      const Scene scene = read_scene_xml(input);
      garment_path = scene_relative(input, scene.garment_file);
      text.material = scene.material.name;
      if (!scene.name.empty()) text.style_name = scene.name;
    }
    const Garment g = read_garment(garment_path);
    const double read_ms = elapsed_ms(start);

    const auto pieces_start = std::chrono::steady_clock::now();
    PieceParams params;
    params.allowance.allowance = allowance_mm / kMm;
    params.allowance.mitre_limit = mitre_limit;
    CuttingLayout layout;
    try {
      layout = cutting_pieces(g, params);
    } catch (const ArgumentError& e) {
      throw InputError(garment_path, 0, e.what());
    }
    if (merge_pairs) layout.pieces = merge_congruent_pieces(layout.pieces);
    if (!style.empty()) text.style_name = style;
    if (!material.empty()) text.material = material;
    text.author = author;
    text.size = size;
    text.category = category;
    text.creation_date = creation_date();
    text.seam_allowance = params.allowance.allowance;
    const PatternSheet sheet = pattern_sheet(layout.pieces, text);
    const std::string dxf = aama_dxf(layout.pieces, sheet.offsets, text, {.strict = strict});
    const std::string svg = svg_path.empty() ? "" : pattern_svg(sheet);
    const std::vector<unsigned char> png = png_path.empty() ? std::vector<unsigned char>{} : pattern_png(sheet, png_scale);
    const double pieces_ms = elapsed_ms(pieces_start);

    std::vector<SeamRow> rows;
    double worst = 0.0;
    for (const Seam& s : layout.seams) {
      rows.push_back({s.a.panel, s.b.panel, pattern_length(g.P, s.a.vertices, s.closed), pattern_length(g.P, s.b.vertices, s.closed),
                      s.closed});
      worst = std::max(worst, std::abs(rows.back().length_a - rows.back().length_b));
    }
    double allowance_lo = std::numeric_limits<double>::infinity(), allowance_hi = 0.0;
    for (const CuttingPiece& piece : layout.pieces) {
      const auto [lo, hi] = allowance_range(piece);
      allowance_lo = std::min(allowance_lo, lo);
      allowance_hi = std::max(allowance_hi, hi);
    }

    const auto write_start = std::chrono::steady_clock::now();
    check_output_folders({output, svg_path, png_path});
    write_file_atomically(output, [&](std::ostream& out) { out << dxf; });
    if (!svg_path.empty()) write_file_atomically(svg_path, [&](std::ostream& out) { out << svg; });
    if (!png_path.empty())
      write_file_atomically(png_path, [&](std::ostream& out) { out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size())); });
    const double write_ms = elapsed_ms(write_start);

    std::string report;
    if (as_json) {
      JsonWriter j;
      j.begin_object().key("patterns").value(garment_path).key("dxf").value(output);
      j.key("svg").value(svg_path).key("png").value(png_path);
      j.key("seam_allowance_mm").value(allowance_mm).key("strict").value(strict);
      j.key("pieces").begin_array();
      for (size_t i = 0; i < layout.pieces.size(); ++i) {
        const CuttingPiece& p = layout.pieces[i];
        j.begin_object().key("panel").value(p.name).key("block").value(sheet.names[i]);
        j.key("cut_vertices").value(p.cut.outer.size()).key("cut_outs").value(p.cut.holes.size());
        j.key("notches").value(p.notches.size()).key("area_mm2").value(signed_area(p.sew.front()) * kMm * kMm);
        j.key("quantity").value(p.quantity);
        j.key("instruction").value(cutting_instruction(layout.pieces, sheet.names, static_cast<int>(i)));
        j.end_object();
      }
      j.end_array().key("seams").begin_array();
      for (const SeamRow& r : rows) {
        j.begin_object().key("panel_a").value(g.panels[r.panel_a].name).key("panel_b").value(g.panels[r.panel_b].name);
        j.key("length_a_mm").value(r.length_a * kMm).key("length_b_mm").value(r.length_b * kMm);
        j.key("difference_mm").value((r.length_a - r.length_b) * kMm).key("closed").value(r.closed).end_object();
      }
      j.end_array().key("max_seam_difference_mm").value(worst * kMm);
      j.key("allowance_check_mm").begin_array().value(allowance_lo * kMm).value(allowance_hi * kMm).end_array();
      j.key("time_ms").begin_object().key("read").value(read_ms).key("pieces").value(pieces_ms).key("write").value(write_ms);
      j.end_object().end_object();
      report = j.str() + "\n";
    } else {
      report += fmt("export-dxf  %s -> %s", garment_path.c_str(), output.c_str());
      if (!svg_path.empty()) report += ", " + svg_path;
      if (!png_path.empty()) report += ", " + png_path;
      report += fmt("  (seam allowance %g mm%s)\n\n", allowance_mm, strict ? ", strict" : "");
      report += fmt("%-16s %-16s %12s %8s %11s  %s\n", "piece", "block", "cut vertices", "notches", "area [cm2]", "cutting");
      for (size_t i = 0; i < layout.pieces.size(); ++i) {
        const CuttingPiece& p = layout.pieces[i];
        report += fmt("%-16s %-16s %12zu %8zu %11.1f  %s\n", p.name.c_str(), sheet.names[i].c_str(), p.cut.outer.size(),
                      p.notches.size(), signed_area(p.sew.front()) * 1e4,
                      cutting_instruction(layout.pieces, sheet.names, static_cast<int>(i)).c_str());
      }
      report += fmt("\n%-4s %-16s %-16s %14s %14s %10s\n", "seam", "panel a", "panel b", "length a [mm]", "length b [mm]", "diff [mm]");
      for (size_t i = 0; i < rows.size(); ++i)
        report += fmt("%-4zu %-16s %-16s %14.2f %14.2f %10.3f%s\n", i + 1, g.panels[rows[i].panel_a].name.c_str(),
                      g.panels[rows[i].panel_b].name.c_str(), rows[i].length_a * kMm, rows[i].length_b * kMm,
                      shown((rows[i].length_a - rows[i].length_b) * kMm), rows[i].closed ? "  closed" : "");
      report += fmt("\nlargest seam difference %.3f mm over %zu seams; cut line %.3f..%.3f mm from the sew line\n", worst * kMm,
                    rows.size(), allowance_lo * kMm, allowance_hi * kMm);
      report += fmt("time  read %.0f ms, pieces %.0f ms, write %.0f ms\n", read_ms, pieces_ms, write_ms);
    }
    (output == "-" ? std::cerr : std::cout) << report;
  });
}
