// Malformed inputs: each makes the tools exit 1 with "tool: path:line: message" (or
// "tool: path: message") on stderr, and no output file appears.
#include <filesystem>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

class BadInput : public ::testing::Test {
protected:
  void SetUp() override {
    folder = test::temp_folder();
    good_obj = test::read_text(test::source_path("samples/flag/garment.obj"));
    std::filesystem::copy(test::source_path("samples/flag/body.obj"), folder + "/body.obj");
    std::filesystem::copy(test::source_path("samples/flag/garment.obj"), folder + "/garment.obj");
  }

  // Runs `tool ARGS input -o OUT`: expects exit 1, exactly `expected` on stderr, no OUT.
  void expect_rejected(const std::string& tool, const std::string& input, const std::string& expected) {
    const std::string out = folder + "/out-" + tool;
    const auto r = test::run(test::tool_path(tool) + " " + input + " -o " + out);
    EXPECT_EQ(r.status, 1) << tool << " " << input;
    EXPECT_EQ(r.err, tool + ": " + expected + "\n");
    EXPECT_FALSE(std::filesystem::exists(out)) << tool << " wrote " << out;
  }
  void expect_obj_rejected(const std::string& text, const std::string& message_after_path) {
    const std::string path = folder + "/bad.obj";
    test::write_text(path, text);
    for (const char* tool : {"garment-info", "export-ply", "export-dxf"}) expect_rejected(tool, path, path + message_after_path);
  }
  void expect_scene_rejected(const std::string& xml, const std::string& message_after_path) {
    const std::string path = folder + "/scene.xml";
    test::write_text(path, xml);
    expect_rejected("garment-info", path, path + message_after_path);
  }

  std::string folder, good_obj;
};

TEST_F(BadInput, TruncatedObj) {
  // Cut the file in the middle of a v line: that line has too few coordinates.
  const size_t cut = good_obj.find("\nv ", good_obj.size() / 8) + 8;
  const std::string truncated = good_obj.substr(0, cut);
  const int line = static_cast<int>(std::count(truncated.begin(), truncated.end(), '\n')) + 1;
  const std::string path = folder + "/bad.obj";
  test::write_text(path, truncated);
  const auto r = test::run(test::tool_path("garment-info") + " " + path + " -o " + folder + "/out");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("garment-info: " + path + ":" + std::to_string(line) + ": ", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/out"));
}

TEST_F(BadInput, ObjCutAfterTheVertices) {
  expect_obj_rejected(good_obj.substr(0, good_obj.find("\ng ")), ": no faces: a garment needs triangles (f v/vt lines)");
}

TEST_F(BadInput, FaceIndexOutOfRange) {
  expect_obj_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\ng p\nf 1/1 2/2 9/3\n",
                      ":8: face refers to v 9 but the file has 3 v lines");
}

TEST_F(BadInput, FaceWithoutVt) {
  expect_obj_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\ng p\nf 1 2 3\n",
                      ":5: face corner '1' has no vt index: every corner needs its pattern position (f v/vt)");
}

TEST_F(BadInput, NaNCoordinate) {
  expect_obj_rejected("v 0 0 0\nv 1 NaN 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", ":2: non-finite y coordinate 'NaN'");
}

TEST_F(BadInput, MissingGarmentFile) {
  for (const char* tool : {"garment-info", "export-ply"})
    expect_rejected(tool, folder + "/absent.obj", folder + "/absent.obj: no such file");
}

TEST_F(BadInput, BrokenXml) {
  const std::string path = folder + "/scene.xml";
  test::write_text(path, "<scene>\n  <garment file=\"garment.obj\"\n  <material preset=\"silk\"/>\n</scene>\n");
  const auto r = test::run(test::tool_path("garment-info") + " " + path + " -o " + folder + "/out");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("garment-info: " + path + ":2: malformed XML", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/out"));
}

TEST_F(BadInput, UnknownMaterialPreset) {
  expect_scene_rejected("<scene>\n  <garment file=\"garment.obj\"/>\n  <body file=\"body.obj\"/>\n  <material preset=\"tweed\"/>\n</scene>\n",
                        ":4: unknown material preset 'tweed' (known: cotton-thin, cotton-thick, knit, denim, silk, leather)");
}

TEST_F(BadInput, MissingBodyFile) {
  expect_scene_rejected("<scene>\n  <garment file=\"garment.obj\"/>\n  <body file=\"mannequin.obj\"/>\n  <material preset=\"silk\"/>\n</scene>\n",
                        ":3: <body> names file 'mannequin.obj', which does not exist");
}

TEST_F(BadInput, InputsAreNeverModified) {
  const std::string before = test::read_text(folder + "/garment.obj");
  const auto r = test::run(test::tool_path("export-ply") + " " + folder + "/garment.obj -o " + folder + "/view.ply");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_text(folder + "/garment.obj"), before);
}

} // namespace
} // namespace foldsketch
