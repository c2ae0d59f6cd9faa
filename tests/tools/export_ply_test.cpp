#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(ExportPly, WritesEveryPanelCorner) {
  const std::string out = test::temp_folder() + "/skirt.ply";
  const auto r = test::run(test::tool_path("export-ply") + " " + test::source_path("samples/skirt/garment.obj") + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string ply = test::read_text(out);
  EXPECT_EQ(ply.rfind("ply\nformat ascii 1.0\n", 0), 0u);
  const auto info = test::run(test::tool_path("garment-info") + " --json " + test::source_path("samples/skirt/garment.obj"));
  const auto field = [&](const std::string& key) {
    const auto at = info.out.find("\"" + key + "\":");
    return info.out.substr(at + key.size() + 3, info.out.find(',', at) - at - key.size() - 3);
  };
  EXPECT_NE(ply.find("element vertex " + field("pattern_vertices") + "\n"), std::string::npos);
  EXPECT_NE(ply.find("element face " + field("triangles") + "\n"), std::string::npos);
}

} // namespace
} // namespace foldsketch
