#include "formats/scene_xml.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/body_mesh.h"
#include "formats/garment_io.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

class SceneXml : public ::testing::Test {
protected:
  void SetUp() override {
    folder = test::temp_folder();
    write_garment(test::two_sewn_squares(), folder + "/garment.obj");
    write_mesh_obj(box_mesh({0, 0, 0}, {1, 1, 1}), folder + "/body.obj");
  }
  std::string error_of(const std::string& xml) {
    test::write_text(folder + "/scene.xml", xml);
    try {
      read_scene_xml(folder + "/scene.xml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::string folder;
};

TEST_F(SceneXml, WrittenSceneReadsBackEqual) {
  Scene s;
  s.name = "test & <scene>";
  s.garment_file = "garment.obj";
  s.body = BodySettings{"body.obj", 0.003};
  s.material = *material_preset("denim");
  s.material.bending = 1e-4;  // a preset with an override is written as SI values
  s.gravity = {0, 0, -9.81};
  s.physics = {false, true, false, true};
  VertexSelector box;
  box.box = Eigen::AlignedBox3d(Vector3d(-1, 0.5, -1), Vector3d(1, 0.6, 1));
  VertexSelector list;
  list.vertices = {0, 4};
  s.pins = {box, list};
  VertexSelector pleat;
  pleat.box = Eigen::AlignedBox3d(Vector3d(-0.2, 0.1, -0.3), Vector3d(0.2, 0.4, 0.3));
  pleat.vertices = {7};
  s.self_contact_regions = {pleat};
  s.simulator = {SimulationMode::Dynamic, SolverPreset::Fast, 0.005, 300, 1e-5};
  write_scene_xml(s, folder + "/scene.xml");
  const Scene r = read_scene_xml(folder + "/scene.xml");
  EXPECT_EQ(r.name, s.name);
  EXPECT_EQ(r.garment_file, "garment.obj");
  ASSERT_TRUE(r.body);
  EXPECT_EQ(r.body->thickness, 0.003);
  EXPECT_EQ(r.material.bending, 1e-4);
  EXPECT_EQ(r.material.density, s.material.density);
  EXPECT_EQ(r.material.name, "custom");
  EXPECT_EQ(r.gravity, s.gravity);
  EXPECT_FALSE(r.physics.body_contact);
  EXPECT_TRUE(r.physics.self_contact);
  EXPECT_TRUE(r.physics.hemline);
  ASSERT_EQ(r.pins.size(), 2u);
  EXPECT_TRUE(r.pins[0].box->isApprox(*box.box));
  EXPECT_EQ(r.pins[1].vertices, list.vertices);
  ASSERT_EQ(r.self_contact_regions.size(), 1u);
  EXPECT_TRUE(r.self_contact_regions[0].box->isApprox(*pleat.box));
  EXPECT_EQ(r.self_contact_regions[0].vertices, pleat.vertices);
  EXPECT_EQ(r.simulator.mode, SimulationMode::Dynamic);
  EXPECT_EQ(r.simulator.preset, SolverPreset::Fast);
  EXPECT_EQ(r.simulator.max_steps, 300);
  EXPECT_EQ(r.simulator.tolerance, 1e-5);
}

TEST_F(SceneXml, PresetNamesAreKept) {
  test::write_text(folder + "/scene.xml", "<scene><garment file=\"garment.obj\"/><material preset=\"silk\"/>"
                                          "<physics body-contact=\"false\"/></scene>");
  const Scene r = read_scene_xml(folder + "/scene.xml");
  EXPECT_EQ(r.material.name, "silk");
  EXPECT_FALSE(r.body);
}

TEST_F(SceneXml, BadScenesNameFileAndLine) {
  const std::string path = folder + "/scene.xml";
  EXPECT_EQ(error_of("<scene>\n  <garment file=\"garment.obj\"/>\n  <body file=\"body.obj\"/>\n  <material preset=\"velvet\"/>\n</scene>\n"),
            path + ":4: unknown material preset 'velvet' (known: cotton-thin, cotton-thick, knit, denim, silk, leather)");
  EXPECT_EQ(error_of("<scene>\n  <garment file=\"garment.obj\"/>\n  <body file=\"nobody.obj\"/>\n</scene>\n"),
            path + ":3: <body> names file 'nobody.obj', which does not exist");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\" density=\"-2\"/>\n</scene>"),
            path + ":3: material: density must be a positive number of kg/m^2");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n<wind/>\n</scene>"),
            path + ":4: unknown element <wind> (known: garment, body, material, gravity, physics, pin, self-contact, simulator)");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\" scale=\"2\"/>\n</scene>"),
            path + ":2: unknown attribute 'scale' on <garment> (known: file)");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n</scene>"),
            path + ":1: body contact is on but the scene names no <body file=...>");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n<physics body-contact=\"maybe\"/>\n</scene>"),
            path + ":4: attribute body-contact of <physics>: expected true or false, found 'maybe'");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<pin box=\"0 0 0 1 1\"/>\n</scene>"),
            path + ":3: <pin box> needs 'xmin ymin zmin xmax ymax zmax' with min <= max [m]");
  // A self-contact region names the element it is on, and needs the switch.
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n<physics body-contact=\"false\" "
                     "self-contact=\"true\"/>\n<self-contact vertices=\"3 x\"/>\n</scene>"),
            path + ":5: <self-contact vertices>: expected 1-based drape vertex numbers, found 'x'");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n<physics body-contact=\"false\"/>\n"
                     "<self-contact box=\"0 0 0 1 1 1\"/>\n<self-contact vertices=\"1\"/>\n</scene>"),
            path + ":5: <self-contact> gives a region but self-contact is off (<physics self-contact=\"true\"/>)");
  EXPECT_EQ(error_of("<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"silk\"/>\n<physics body-contact=\"false\" "
                     "self-contact=\"true\"/>\n<self-contact/>\n</scene>"),
            path + ":5: <self-contact> needs a box or vertices attribute");
  // Broken XML: tinyxml2's line of the problem.
  const std::string broken = error_of("<scene>\n<garment file=\"garment.obj\">\n<material preset=\"silk\"/>\n</scene>\n");
  EXPECT_EQ(broken.rfind(path + ":", 0), 0u) << broken;
  EXPECT_NE(broken.find("malformed XML"), std::string::npos) << broken;
  EXPECT_EQ(error_of(""), path + ": malformed XML: the file is empty");
}

TEST_F(SceneXml, MissingSceneFileIsReported) {
  try {
    read_scene_xml(folder + "/none.xml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), folder + "/none.xml: no such file");
  }
}

} // namespace
} // namespace foldsketch
