// The committed samples are made by code in the repo: make-sample writes their scenes and
// patterns exactly, and their drapes are equilibria of the cloth engine (samples/regenerate.sh).
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

// The OBJ without its v lines: the patterns, panels and triangles.
std::string patterns_of(const std::string& obj) {
  std::string out, line;
  std::istringstream in(obj);
  while (std::getline(in, line))
    if (line.rfind("v ", 0) != 0) out += line + "\n";
  return out;
}

TEST(MakeSample, RegeneratesTheCommittedSamplesByteForByte) {
  // Rebuild the samples/ layout (bodies/ beside the scenes) so relative body paths match.
  const std::string root = test::temp_folder();
  std::filesystem::create_directories(root + "/bodies");
  std::filesystem::copy(test::source_path("samples/bodies/mean_all.obj"), root + "/bodies/mean_all.obj");
  for (const std::string name : {"flag", "skirt", "box-cover", "dress"}) {
    const auto r = test::run(test::tool_path("make-sample") + " " + name + " --mesh isotropic --body " + root +
                             "/bodies/mean_all.obj -o " + root + "/" + name);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const std::string file : {"scene.xml", "body.obj"}) {
      const std::string committed = test::source_path("samples/" + name + "/" + file);
      if (!std::filesystem::exists(committed)) continue;
      EXPECT_TRUE(test::read_text(root + "/" + name + "/" + file) == test::read_text(committed)) << committed << " differs";
    }
    // The committed garment is the simulated drape of these patterns: same vt, g and f lines.
    const std::string committed = test::source_path("samples/" + name + "/garment.obj");
    EXPECT_TRUE(patterns_of(test::read_text(root + "/" + name + "/garment.obj")) == patterns_of(test::read_text(committed)))
        << committed << ": patterns differ from make-sample's";
  }
}

TEST(MakeSample, AnySizeOnDemand) {
  const std::string folder = test::temp_folder() + "/flag";
  const auto r = test::run(test::tool_path("make-sample") + " flag --triangles 20000 --json -o " + folder);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"triangles\":19866"), std::string::npos) << r.out;
}

TEST(MakeSample, FittedSamplesNeedABody) {
  const std::string folder = test::temp_folder() + "/skirt";
  const auto r = test::run(test::tool_path("make-sample") + " skirt -o " + folder);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "make-sample: sample 'skirt' needs --body\n");
  EXPECT_FALSE(std::filesystem::exists(folder));
  EXPECT_EQ(test::run(test::tool_path("make-sample") + " cape -o " + folder).status, 2);
}

} // namespace
} // namespace foldsketch
