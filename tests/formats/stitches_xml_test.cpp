#include "formats/stitches_xml.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/garment_io.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(StitchesXml, SidecarTravelsWithTheGarment) {
  Garment g = test::two_sewn_squares();
  g.stitches = {{{0, -1, 0}, {5, -1, 0}}, {{1, -1, 0}, {3, 4, 0.25}}, {{2, -1, 0}, {3, 4, 1.0 / 3.0}}};
  const std::string path = test::temp_folder() + "/pleated.obj";
  write_garment(g, path);
  EXPECT_EQ(stitches_path(path), std::filesystem::path(path).parent_path().string() + "/pleated.stitches.xml");
  EXPECT_TRUE(std::filesystem::exists(stitches_path(path)));
  EXPECT_EQ(read_garment(path), g);
  // Written again without stitches: the stale sidecar goes, so reading gives no stitches.
  g.stitches.clear();
  write_garment(g, path);
  EXPECT_FALSE(std::filesystem::exists(stitches_path(path)));
  EXPECT_EQ(read_garment(path), g);
}

TEST(StitchesXml, BadStitchesNameTheirLine) {
  const std::string folder = test::temp_folder();
  const Garment g = test::two_sewn_squares();
  write_garment(g, folder + "/g.obj");
  const auto error_of = [&](const std::string& xml) -> std::string {
    test::write_text(folder + "/g.stitches.xml", xml);
    try {
      read_garment(folder + "/g.obj");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  const std::string sidecar = folder + "/g.stitches.xml";
  EXPECT_EQ(error_of("<stitches>\n  <stitch a=\"1\" b=\"99\"/>\n</stitches>\n"),
            sidecar + ":2: stitch names drape vertex 99 but " + folder + "/g.obj has 6");
  EXPECT_EQ(error_of("<stitches>\n<stitch a=\"1\" b=\"2 3 1.5\"/>\n</stitches>\n"),
            sidecar + ":2: attribute b of <stitch>: expected T in [0, 1], found '1.5'");
  EXPECT_EQ(error_of("<stitches>\n<stitch a=\"x\" b=\"2\"/>\n</stitches>\n"),
            sidecar + ":2: attribute a of <stitch>: expected a 1-based vertex number, found 'x'");
  EXPECT_EQ(error_of("<stitches>\n<seam a=\"1\" b=\"2\"/>\n</stitches>\n"), sidecar + ":2: unknown element <seam> in <stitches>");
  EXPECT_NE(error_of("<stitches>\n<stitch a=\"1\" b=\"2\">\n").find(sidecar + ":"), std::string::npos);
}

} // namespace
} // namespace foldsketch
