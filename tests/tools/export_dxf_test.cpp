// export-dxf, checked from outside: its DXF is read back with ezdxf (Debian's python3-ezdxf, run as
// /usr/bin/python3), its SVG parsed and rendered with rsvg-convert, by
// tests/tools/check_cutting_patterns.py, which parses the garment OBJ on its own.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "formats/garment_io.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

std::string checker() { return "/usr/bin/python3 " + test::source_path("tests/tools/check_cutting_patterns.py"); }

void expect_check(const std::string& args) {
  const auto r = test::run(checker() + " " + args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out << r.err;
}

// Runs export-dxf on `input` into `folder`, then the DXF, SVG and seam checks.
void export_and_check(const std::string& input, const std::string& garment, const std::string& folder, double allowance_mm,
                      int min_seams, const std::string& extra = "") {
  const std::string dxf = folder + "/pieces.dxf", svg = folder + "/pieces.svg", report = folder + "/report.json";
  const auto r = test::run(test::tool_path("export-dxf") + " " + input + " -o " + dxf + " --svg " + svg +
                           " --seam-allowance " + std::to_string(allowance_mm) + " --json " + extra);
  ASSERT_EQ(r.status, 0) << r.err;
  test::write_text(report, r.out);
  const std::string allowance = std::to_string(allowance_mm);
  expect_check("dxf " + dxf + " " + garment + " " + allowance + (extra.find("--strict") != std::string::npos ? " --strict" : ""));
  expect_check("svg " + svg + " " + garment + " " + allowance);
  expect_check("seams " + report + " 0.01 " + std::to_string(min_seams));
}

class ExportDxfSample : public ::testing::TestWithParam<std::pair<std::string, int>> {};

// Every sample: the strict ezdxf reader loads it, audit reports no errors, one block per panel,
// each INSERTed once, one closed layer-1 polyline per block matching outline + 10 mm within
// 0.01 mm, piece and style texts, only convention layers, unique block names; the SVG is 1:1
// and renders; matched seams are equal within 0.01 mm.
TEST_P(ExportDxfSample, PassesTheIndependentChecks) {
  const auto& [name, seams] = GetParam();
  const std::string scene = test::source_path("samples/" + name + "/scene.xml");
  export_and_check(scene, test::source_path("samples/" + name + "/garment.obj"), test::temp_folder(), 10.0, seams);
}

INSTANTIATE_TEST_SUITE_P(Samples, ExportDxfSample,
                         ::testing::Values(std::pair{std::string("flag"), 0}, std::pair{std::string("skirt"), 2},
                                           std::pair{std::string("box-cover"), 8}, std::pair{std::string("dress"), 6}),
                         [](const auto& param_info) {
                           std::string n = param_info.param.first;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

// Real garments (Berkeley Garment Library, ARCSim convention: no groups, per-corner vt). Their
// seams are not all matched (gathers), so only the DXF and SVG checks apply.
TEST(ExportDxf, BerkeleyGarmentLibraryGarments) {
  if (!test::shared_available()) GTEST_SKIP() << "../shared/data/bgl is absent: BGL garments not exported";
  for (const char* file : {"skirt/isotropic/skirt-iso.obj", "tshirt/isotropic/tshirt-iso.obj", "pants/isotropic/pants-iso.obj",
                           "dress/isotropic/dress3-iso.obj"}) {
    const std::string obj = test::shared_path(std::string("data/bgl/Garments/") + file);
    const std::string folder = test::temp_folder();
    const auto r = test::run(test::tool_path("export-dxf") + " " + obj + " -o " + folder + "/p.dxf --svg " + folder + "/p.svg");
    ASSERT_EQ(r.status, 0) << file << ": " << r.err;
    expect_check("dxf " + folder + "/p.dxf " + obj + " 10");
    expect_check("svg " + folder + "/p.svg " + obj + " 10");
  }
}

TEST(ExportDxf, NoAllowanceCutsOnTheOutlineAndStrictHoldsOnlyInserts) {
  export_and_check(test::source_path("samples/dress/scene.xml"), test::source_path("samples/dress/garment.obj"),
                   test::temp_folder(), 0.0, 6, "--strict");
}

// Hard outlines, one panel each: the cut line must stay simple and exactly one allowance out.
MatrixX2d outline(std::initializer_list<std::pair<double, double>> points) {
  MatrixX2d m(static_cast<long>(points.size()), 2);
  long i = 0;
  for (const auto& [x, y] : points) m.row(i++) << x, y;
  return m;
}

class ExportDxfHardOutline : public ::testing::TestWithParam<std::string> {};

TEST_P(ExportDxfHardOutline, CutLineIsSimpleAndOneAllowanceOut) {
  const std::string& kind = GetParam();
  Garment g;
  if (kind == "concave") {
    // A comb: three 12 mm teeth with 8 mm gaps, deeper than the gaps are wide.
    g = test::polygon_panel("comb", outline({{0, 0}, {0.06, 0}, {0.06, 0.1}, {0.048, 0.1}, {0.048, 0.04}, {0.04, 0.04}, {0.04, 0.1},
                                             {0.028, 0.1}, {0.028, 0.04}, {0.02, 0.04}, {0.02, 0.1}, {0, 0.1}}),
                            0.006);
  } else if (kind == "short_edges") {
    // A zigzag edge of 0.4 mm steps, and a 0.2 mm edge at a corner.
    std::vector<std::pair<double, double>> p{{0, 0}, {0.1, 0}, {0.1, 0.0998}, {0.0998, 0.1}};
    for (int k = 0; k < 20; ++k) p.emplace_back(0.09 - 0.004 * k, k % 2 ? 0.1 : 0.1004);
    p.emplace_back(0, 0.1);
    MatrixX2d m(static_cast<long>(p.size()), 2);
    for (size_t i = 0; i < p.size(); ++i) m.row(static_cast<long>(i)) << p[i].first, p[i].second;
    g = test::polygon_panel("zigzag", m, 0.01);
  } else if (kind == "strip") {
    g = test::polygon_panel("strip", outline({{0, 0}, {0.3, 0}, {0.3, 0.005}, {0, 0.005}}), 0.0025);
  } else if (kind == "hole") {
    g = test::polygon_panel("window", outline({{0, 0}, {0.2, 0}, {0.2, 0.15}, {0, 0.15}}), 0.01,
                            {outline({{0.05, 0.05}, {0.05, 0.1}, {0.15, 0.1}, {0.15, 0.05}})});
  } else if (kind == "spike") {
    const double t = std::tan(10.0 * std::numbers::pi / 180.0);
    g = test::polygon_panel("dart", outline({{0, 0}, {0.15, -0.15 * t}, {0.15, 0.15 * t}}), 0.004);
  }
  const std::string folder = test::temp_folder() + "/" + kind;
  std::filesystem::create_directories(folder);
  const std::string obj = folder + "/garment.obj";
  write_garment(g, obj);
  export_and_check(obj, obj, folder, 10.0, 0);
}

INSTANTIATE_TEST_SUITE_P(Outlines, ExportDxfHardOutline,
                         ::testing::Values("concave", "short_edges", "strip", "hole", "spike"),
                         [](const auto& param_info) { return param_info.param; });

TEST(ExportDxf, PngPreviewHasThePageSizeAtTheChosenScale) {
  const std::string folder = test::temp_folder();
  const auto r = test::run(test::tool_path("export-dxf") + " " + test::source_path("samples/box-cover/scene.xml") + " -o " +
                           folder + "/p.dxf --svg " + folder + "/p.svg --png " + folder + "/p.png --png-scale 1");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream png(folder + "/p.png", std::ios::binary);
  unsigned char head[24] = {};
  png.read(reinterpret_cast<char*>(head), sizeof head);
  ASSERT_EQ(std::string(reinterpret_cast<char*>(head + 1), 3), "PNG");
  const auto be32 = [&](int at) { return (head[at] << 24) | (head[at + 1] << 16) | (head[at + 2] << 8) | head[at + 3]; };
  const std::string svg = test::read_text(folder + "/p.svg");
  const auto attribute = [&](const std::string& key) {
    const auto at = svg.find(key + "=\"") + key.size() + 2;
    return std::stod(svg.substr(at, svg.find("mm\"", at) - at));
  };
  EXPECT_EQ(be32(16), static_cast<int>(std::ceil(attribute("width"))));
  EXPECT_EQ(be32(20), static_cast<int>(std::ceil(attribute("height"))));
}

TEST(ExportDxf, NamesAreAsciiUniqueAndCaseInsensitive) {
  // Three panels whose names collide once upper-cased or made ASCII.
  Garment g = test::polygon_panel("Front", outline({{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}}), 0.02);
  for (const std::string name : {"front", "\xc3\x84rmel"}) {
    Garment h = test::polygon_panel(name, outline({{0, 0}, {0.1, 0}, {0.1, 0.05}, {0, 0.05}}), 0.02);
    const long v = g.V.rows(), p = g.P.rows(), f = g.F.rows();
    g.V.conservativeResize(v + h.V.rows(), 3);
    g.V.bottomRows(h.V.rows()) = h.V.rowwise() + Eigen::RowVector3d(0.0, 0.2 * static_cast<double>(g.panels.size()), 0.0);
    g.P.conservativeResize(p + h.P.rows(), 2);
    g.P.bottomRows(h.P.rows()) = h.P;
    g.F.conservativeResize(f + h.F.rows(), 3);
    g.F.bottomRows(h.F.rows()) = h.F.array() + static_cast<int>(v);
    g.FP.conservativeResize(f + h.F.rows(), 3);
    g.FP.bottomRows(h.F.rows()) = h.FP.array() + static_cast<int>(p);
    g.face_panel.conservativeResize(f + h.F.rows());
    g.face_panel.tail(h.F.rows()).setConstant(static_cast<int>(g.panels.size()));
    g.panels.push_back(h.panels[0]);
  }
  const std::string folder = test::temp_folder();
  write_garment(g, folder + "/g.obj");
  export_and_check(folder + "/g.obj", folder + "/g.obj", folder, 10.0, 0);
  const std::string dxf = test::read_text(folder + "/pieces.dxf");
  for (const char* name : {"\nFRONT\n", "\nFRONT_2\n", "\n_RMEL\n"}) EXPECT_NE(dxf.find(name), std::string::npos) << name;
}

TEST(ExportDxf, WritesNothingWhenAnOutputFolderIsMissing) {
  const std::string folder = test::temp_folder();
  const auto r = test::run(test::tool_path("export-dxf") + " " + test::source_path("samples/skirt/scene.xml") + " -o " + folder +
                           "/p.dxf --svg " + folder + "/missing/p.svg");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/p.dxf"));
}

TEST(ExportDxf, UsageErrorsExitTwo) {
  const std::string folder = test::temp_folder();
  const std::string tool = test::tool_path("export-dxf") + " " + test::source_path("samples/skirt/scene.xml");
  EXPECT_EQ(test::run(tool + " -o " + folder + "/p.dxf --seam-allowance -3").status, 2);
  EXPECT_EQ(test::run(tool).status, 2);  // no -o
  EXPECT_EQ(test::run(tool + " -o " + folder + "/p.dxf --bogus").status, 2);
  EXPECT_FALSE(std::filesystem::exists(folder + "/p.dxf"));
  EXPECT_EQ(test::run(test::tool_path("export-dxf") + " --help").status, 0);
}

TEST(ExportDxf, MergedPairsAreCutTwiceFromOnePiece) {
  const std::string folder = test::temp_folder();
  const std::string garment = test::source_path("samples/box-cover/garment.obj");
  const auto r = test::run(test::tool_path("export-dxf") + " " + garment + " -o " + folder + "/p.dxf --merge-pairs");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string dxf = test::read_text(folder + "/p.dxf");
  // Five panels: the top, and front/back and left/right cut from one pattern each.
  int blocks = 0, twice = 0;
  for (auto at = dxf.find("\nBLOCK\n"); at != std::string::npos; at = dxf.find("\nBLOCK\n", at + 1)) ++blocks;
  for (auto at = dxf.find("Quantity: 2\n"); at != std::string::npos; at = dxf.find("Quantity: 2\n", at + 1)) ++twice;
  EXPECT_EQ(blocks, 3);
  EXPECT_EQ(twice, 2);
  EXPECT_NE(dxf.find("Annotation: cut 2 (front and back)"), std::string::npos);
  expect_check("dxf " + folder + "/p.dxf " + garment + " 10 --merged");
}

// The checker must fail on the defects it is there to catch; otherwise the tests above prove nothing.
TEST(ExportDxf, CheckerCatchesDefects) {
  const std::string folder = test::temp_folder();
  const std::string garment = test::source_path("samples/box-cover/garment.obj");
  ASSERT_EQ(test::run(test::tool_path("export-dxf") + " " + garment + " -o " + folder + "/good.dxf").status, 0);
  const std::string good = test::read_text(folder + "/good.dxf");
  const auto replace_first = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    return at == std::string::npos ? std::string() : text.replace(at, from.size(), to);
  };
  const std::vector<std::pair<std::string, std::string>> defects{
      // A cut-line vertex moved by 1 mm: the first VERTEX's x.
      {"moved vertex", [&] {
         const auto v = good.find("VERTEX\n  8\n1\n 10\n");
         std::string t = good;
         const auto at = v + std::string("VERTEX\n  8\n1\n 10\n").size();
         const auto end = t.find('\n', at);
         return t.replace(at, end - at, std::to_string(std::stod(t.substr(at, end - at)) + 1.0));
       }()},
      {"duplicate block name", replace_first(good, "\n  2\nFRONT\n", "\n  2\nBACK\n")},
      {"entity on layer 0", replace_first(good, "LINE\n  8\n7\n", "LINE\n  8\n0\n")},
      {"missing piece text", replace_first(good, "Material: ", "Fabric: ")},
  };
  for (const auto& [what, text] : defects) {
    ASSERT_FALSE(text.empty()) << what;
    test::write_text(folder + "/bad.dxf", text);
    const auto r = test::run(checker() + " dxf " + folder + "/bad.dxf " + garment + " 10");
    EXPECT_NE(r.status, 0) << what << " went unnoticed:\n" << r.out;
  }
  test::write_text(folder + "/good-copy.dxf", good);
  EXPECT_EQ(test::run(checker() + " dxf " + folder + "/good-copy.dxf " + garment + " 10").status, 0);
}

} // namespace
} // namespace foldsketch
