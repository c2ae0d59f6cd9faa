// The CLI layer's restart with huge pages: the tunable it sets, and that a restarted drape-free
// computes exactly what an unrestarted one does.
#include "cli.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(HugePages, AddsTheTunableToWhatIsSet) {
  EXPECT_EQ(huge_page_tunables(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(huge_page_tunables(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(huge_page_tunables("glibc.malloc.tcache_count=0"), "glibc.malloc.tcache_count=0:glibc.malloc.hugetlb=1");
}

TEST(HugePages, LeavesTheUsersOwnSettingAndTheRestartedProcessAlone) {
  EXPECT_EQ(huge_page_tunables("glibc.malloc.hugetlb=0"), std::nullopt);
  EXPECT_EQ(huge_page_tunables("glibc.malloc.hugetlb=1"), std::nullopt);
  EXPECT_EQ(huge_page_tunables("glibc.malloc.check=0:glibc.malloc.hugetlb=2"), std::nullopt);
}

TEST(HugePages, ARestartedDrapeIsTheSameDrape) {
  const std::string folder = test::temp_folder() + "/flag";
  ASSERT_EQ(test::run(test::tool_path("make-sample") + " flag --triangles 600 -o " + folder).status, 0);
  const std::string drape = test::tool_path("drape-free") + " " + folder + "/scene.xml -o ";
  // As a user starts it (restarted where the kernel gives huge pages on request), and opted out.
  const auto restarted = test::run("env -u GLIBC_TUNABLES " + drape + folder + "/restarted.obj");
  const auto plain = test::run("env GLIBC_TUNABLES=glibc.malloc.hugetlb=0 " + drape + folder + "/plain.obj");
  ASSERT_EQ(restarted.status, 0) << restarted.err;
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(test::read_text(folder + "/restarted.obj"), test::read_text(folder + "/plain.obj"));
  // A bad argument is refused the same way after the restart.
  const auto refused = test::run("env -u GLIBC_TUNABLES " + drape + folder + "/x.obj --preset slow");
  EXPECT_EQ(refused.status, 2) << refused.err;
}

} // namespace
} // namespace foldsketch
