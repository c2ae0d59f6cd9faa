// garment-info run as a user would: on every sample, human and JSON reports.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

// A standard JSON parser (Python's) checks the report and that both sides of every seam have
// the same length (the samples are sewn from equal lengths).
constexpr const char* kCheckJson =
    "/usr/bin/python3 -c \"import json,sys; d=json.load(open(sys.argv[1])); "
    "assert d['seams'] or d['scene']['name']=='flag', 'no seams'; "
    "bad=[s for s in d['seams'] if abs(s['length_a_mm']-s['length_b_mm'])>1e-6]; "
    "assert not bad, bad; assert d['triangles']>0; print(len(d['seams']))\" ";

class GarmentInfo : public ::testing::TestWithParam<std::string> {};

TEST_P(GarmentInfo, ReportsMatchedSeamsAndParsableJson) {
  const std::string scene = test::source_path("samples/" + GetParam() + "/scene.xml");
  const auto human = test::run(test::tool_path("garment-info") + " " + scene);
  ASSERT_EQ(human.status, 0) << human.err;
  EXPECT_EQ(human.err, "");
  EXPECT_NE(human.out.find("length a [mm]"), std::string::npos);
  EXPECT_NE(human.out.find("material   cotton-thin"), std::string::npos);

  const std::string json = test::temp_folder() + "/info.json";
  const auto machine = test::run(test::tool_path("garment-info") + " --json -o " + json + " " + scene);
  ASSERT_EQ(machine.status, 0) << machine.err;
  const auto parsed = test::run(kCheckJson + json);
  EXPECT_EQ(parsed.status, 0) << parsed.err;
}

INSTANTIATE_TEST_SUITE_P(Samples, GarmentInfo, ::testing::Values("flag", "skirt", "box-cover", "dress"),
                         [](const auto& test_info) { return test_info.param == "box-cover" ? std::string("box_cover") : test_info.param; });

TEST(GarmentInfoTool, ReadsBerkeleyGarmentLibraryFiles) {
  if (!test::shared_available()) GTEST_SKIP() << "../shared/data/bgl is absent";
  const auto r = test::run(test::tool_path("garment-info") + " --json " +
                           test::shared_path("data/bgl/Garments/tshirt/isotropic/tshirt-iso.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"seams\":[{"), std::string::npos);
}

TEST(GarmentInfoTool, HelpSaysWhatItReadsAndUsageErrorsExitTwo) {
  const auto help = test::run(test::tool_path("garment-info") + " --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_EQ(help.out.rfind("Reads a garment OBJ", 0), 0u) << help.out;
  const auto usage = test::run(test::tool_path("garment-info") + " --no-such-flag x.obj");
  EXPECT_EQ(usage.status, 2);
  EXPECT_EQ(usage.err.rfind("garment-info: ", 0), 0u);
  EXPECT_EQ(test::run(test::tool_path("garment-info")).status, 2);
}

} // namespace
} // namespace foldsketch
