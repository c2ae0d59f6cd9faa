#include "formats/garment_obj.h"

#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "garment/garment_issues.h"
#include "garment/seams.h"
#include "samples/sample_scenes.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

Garment parse(const std::string& text) {
  std::istringstream in(text);
  return parse_garment_obj(in, "test.obj");
}

Garment round_trip(const Garment& g) {
  const std::string path = test::temp_folder() + "/g.obj";
  write_garment(g, path);
  return read_garment(path);
}

// The message of the InputError that parsing `text` throws.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(GarmentObj, HandMadeWeldedTwoPanelFileFindsItsSeam) {
  const Garment g = parse(
      "# two panels sharing the drape edge v2-v5\n"
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 3 0\nvt 4 0\nvt 4 1\nvt 3 1\n"
      "g left\nf 1/1 2/2 5/3\nf 1/1 5/3 4/4\n"
      "g right\nf 2/5 3/6 6/7\nf 2/5 6/7 5/8\n");
  ASSERT_EQ(g.panels.size(), 2u);
  EXPECT_EQ(g.panels[0].name, "left");
  const auto s = seams(g, panel_boundaries(g));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(pattern_length(g.P, s[0].a.vertices), 1.0);
  EXPECT_DOUBLE_EQ(pattern_length(g.P, s[0].b.vertices), 1.0);
  EXPECT_EQ(round_trip(g), g);
}

TEST(GarmentObj, RoundTripIsBitExact) {
  Garment g = test::two_sewn_squares();
  // Values with no short decimal spelling, subnormals and negative zero must survive.
  g.V(0, 0) = 0.1 + 0.2;
  g.V(1, 1) = -0.0;
  g.V(2, 2) = 4.9406564584124654e-324;
  g.P(3, 0) = 1.0 / 3.0;
  g.stitches.push_back({{0, -1, 0.0}, {2, 5, 1.0 / 7.0}});
  const Garment back = round_trip(g);
  EXPECT_EQ(back, g);
  EXPECT_TRUE(std::signbit(back.V(1, 1)));
}

TEST(GarmentObj, EverySampleRoundTripsExactly) {
  const TriangleMesh body = read_body_mesh(test::source_path("samples/bodies/mean_all.obj"));
  SampleParams params;
  params.triangles = 4000;
  for (const std::string& name : sample_names()) {
    const Garment g = make_sample(name, params, &body.V).garment;
    EXPECT_EQ(round_trip(g), g) << name;
  }
  for (const std::string& name : sample_names()) {
    const std::string path = test::source_path("samples/" + name + "/garment.obj");
    const Garment g = read_garment(path);
    EXPECT_EQ(round_trip(g), g) << path;
  }
}

TEST(GarmentObj, GroupsMayRepeatAndFacesAreSortedByPanel) {
  const Garment g = parse(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 5 0\nvt 6 0\nvt 5 1\nvt 9 9\nvt 9 8\nvt 8 9\n"
      "g a\nf 1/1 2/2 3/3\ng b\nf 2/4 4/5 3/6\ng a\nf 1/7 2/8 3/9\n");
  ASSERT_EQ(g.panels.size(), 2u);
  EXPECT_EQ(g.face_panel, (VectorXi(3) << 0, 0, 1).finished());
}

TEST(GarmentObj, NegativeIndicesAndPolygonsAreRead) {
  const Garment g = parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\ng quad\nf -4/-4 -3/-3 -2/-2 -1/-1\n");
  EXPECT_EQ(g.F.rows(), 2);
  EXPECT_EQ(g.F.row(1), Eigen::RowVector3i(0, 2, 3));
}

TEST(GarmentObj, UngroupedFilesSplitIntoPanelsByPatternComponents) {
  const Garment g = parse(
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 3 0\nvt 4 0\nvt 4 1\nvt 3 1\n"
      "f 1/1 2/2 5/3\nf 1/1 5/3 4/4\nf 2/5 3/6 6/7\nf 2/5 6/7 5/8\n");
  ASSERT_EQ(g.panels.size(), 2u);
  EXPECT_EQ(g.panels[1].name, "panel-2");
}

TEST(GarmentObj, PerCornerVtFilesAreMergedIntoPatternVertices) {
  // ARCSim / BGL style: one vt per face corner, vv and t lines.
  const Garment g = parse(
      "v 0 0 0\nvv 0 0 0\nv 1 0 0\nvv 0 0 0\nv 1 1 0\nvv 0 0 0\nv 0 1 0\nvv 0 0 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 0\nvt 1 1\nvt 0 1\n"
      "f 1/1 2/2 3/3\nt 0\nf 1/4 3/5 4/6\nt 0\n");
  EXPECT_EQ(g.P.rows(), 4);
  EXPECT_EQ(g.panels.size(), 1u);
  EXPECT_EQ(g.FP(1, 0), g.FP(0, 0));
}

TEST(GarmentObj, BerkeleyGarmentLibraryFilesRead) {
  if (!test::shared_available()) GTEST_SKIP() << "../shared/data/bgl is absent: BGL files not tested";
  for (const char* file : {"skirt/isotropic/skirt-iso.obj", "tshirt/isotropic/tshirt-iso.obj", "pants/isotropic/pants-iso.obj",
                           "dress/isotropic/dress3-iso.obj"}) {
    const std::string path = test::shared_path(std::string("data/bgl/Garments/") + file);
    const Garment g = read_garment(path);
    EXPECT_EQ(garment_structure_error(g), "") << file;
    EXPECT_GE(g.panels.size(), 2u) << file;
    EXPECT_LT(g.P.rows(), 3 * g.F.rows()) << file;  // per-corner vt merged
    const auto s = seams(g, panel_boundaries(g));
    EXPECT_GE(s.size(), 2u) << file;
    EXPECT_TRUE(garment_issues(g).nonfinite_drape_vertices.empty());
    EXPECT_EQ(round_trip(g), g) << file;
  }
}

TEST(GarmentObj, MalformedInputNamesLineAndToken) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 4/3\n"),
            "test.obj:7: face refers to v 4 but the file has 3 v lines");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            "test.obj:4: face corner '1' has no vt index: every corner needs its pattern position (f v/vt)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1//1 2//1 3//1\n"),
            "test.obj:5: face corner '1//1' has no vt index: every corner needs its pattern position (f v/vt)");
  EXPECT_EQ(error_of("v 0 nan 0\n"), "test.obj:1: non-finite y coordinate 'nan'");
  EXPECT_EQ(error_of("v 0 0 0\nvt 1 inf\n"), "test.obj:2: non-finite v coordinate 'inf'");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0"), "test.obj:2: a v line needs 3 coordinates, found 2");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 x\n"), "test.obj:2: expected a number for z coordinate, found 'x'");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2\n"),
            "test.obj:7: a face needs at least 3 corners, found 2");
  EXPECT_EQ(error_of("v 0 0 0\n"), "test.obj: no faces: a garment needs triangles (f v/vt lines)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 2/2 4/1 3/3\n"),
            "test.obj:9: vt 1 is used with v 4 here and with v 1 on line 8: a pattern vertex belongs to one drape vertex");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 0/1 2/2 3/3\n"),
            "test.obj:7: bad v index '0' in face corner '0/1'");
}

} // namespace
} // namespace foldsketch
