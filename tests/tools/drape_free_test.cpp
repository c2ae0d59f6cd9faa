// drape-free run as a batch job would: converged drapes written with exact pins, unconverged
// ones not written (unless asked), bad input refused with a located message.
#include <filesystem>

#include <gtest/gtest.h>

#include "formats/garment_io.h"
#include "formats/scene_xml.h"
#include "sim/cloth_model.h"
#include "support/test_support.h"

namespace foldsketch {
namespace {

std::string make_sample_folder(const std::string& name, int triangles) {
  const std::string folder = test::temp_folder() + "/" + name;
  const auto r = test::run(test::tool_path("make-sample") + " " + name + " --triangles " + std::to_string(triangles) + " -o " + folder);
  EXPECT_EQ(r.status, 0) << r.err;
  return folder;
}

// The sample's scene with one attribute switched (e.g. friction="false" to "true"), written as
// folder/name; returns its path.
std::string switched_scene(const std::string& folder, const std::string& from, const std::string& to, const std::string& name) {
  std::string scene = test::read_text(folder + "/scene.xml");
  const size_t at = scene.find(from);
  EXPECT_NE(at, std::string::npos) << scene;
  if (at != std::string::npos) scene.replace(at, from.size(), to);
  test::write_text(folder + "/" + name, scene);
  return folder + "/" + name;
}

// A drape-free --json run `r`: expects success and the Python `assertions` to hold of its
// report d.
void expect_report(const test::RunResult& r, const std::string& assertions) {
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto check = test::run("/usr/bin/python3 -c \"import json,sys; d=json.loads(sys.argv[1]); " + assertions + "\" '" + r.out + "'");
  EXPECT_EQ(check.status, 0) << check.err;
}

// drape-free --json ARGS on folder's scene, writing folder/draped.obj; expects success, the
// Python `assertions` to hold of its report d, and the drape written on the sample's own mesh
// (patterns unchanged) with every pin exactly where it was and the rest draped.
void expect_drape(const std::string& folder, const std::string& args, const std::string& assertions) {
  const std::string out = folder + "/draped.obj";
  const auto r = test::run(test::tool_path("drape-free") + " --json " + args + " " + folder + "/scene.xml -o " + out);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  expect_report(r, assertions);
  const Garment before = read_garment(folder + "/garment.obj"), after = read_garment(out);
  EXPECT_EQ(after.P, before.P);  // the patterns travel unchanged
  EXPECT_EQ(after.F, before.F);
  const Scene scene = read_scene_xml(folder + "/scene.xml");
  const auto pinned = pinned_vertices(scene, before.V);
  ASSERT_FALSE(pinned.empty());
  for (int v : pinned) EXPECT_EQ(after.V.row(v), before.V.row(v)) << "pin " << v << " moved";
  EXPECT_GT((after.V - before.V).norm(), 0.01);  // and the rest did drape
}

TEST(DrapeFree, ConvergesWithExactPinsAndReportsInJson) {
  expect_drape(make_sample_folder("flag", 600), "",
               "assert d['converged'] and d['residual'] <= 1e-6 and d['factorizations'] > 0 and 'min_self_distance_m' not in d and isinstance(d['double_precision_fallback'], bool), d");
}

TEST(DrapeFree, UnconvergedDrapeIsNotWrittenUnlessAsked) {
  const std::string folder = make_sample_folder("flag", 600);
  const std::string out = folder + "/draped.obj";
  const auto r = test::run(test::tool_path("drape-free") + " --max-steps 2 " + folder + "/scene.xml -o " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("drape-free: did not converge (stopped after 2 iterations"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing written"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--max-steps (or the scene's max-steps) raises the limit"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto kept = test::run(test::tool_path("drape-free") + " --max-steps 2 --write-unconverged " + folder + "/scene.xml -o " + out);
  EXPECT_EQ(kept.status, 1);
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_NE(kept.err.find("wrote the unconverged drape as asked"), std::string::npos) << kept.err;
}

TEST(DrapeFree, BadInputIsLocatedAndWritesNothing) {
  const std::string folder = make_sample_folder("flag", 600);
  test::write_text(folder + "/bad.xml", "<scene>\n<garment file=\"garment.obj\"/>\n<material preset=\"tweed\"/>\n</scene>\n");
  const auto r = test::run(test::tool_path("drape-free") + " " + folder + "/bad.xml -o " + folder + "/out.obj");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("drape-free: " + folder + "/bad.xml:3: unknown material preset 'tweed'", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/out.obj"));
  const std::string friction = switched_scene(folder, "friction=\"false\"", "friction=\"true\"", "friction.xml");
  const auto refused = test::run(test::tool_path("drape-free") + " " + friction + " -o " + folder + "/out.obj");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("friction, which the engine does not model yet"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/out.obj"));
}

// Patterns exported in millimetres (vt 1000 times the drape's metres) are refused at once,
// with the factor, instead of simulated to a dead end; the input stays as it was.
TEST(DrapeFree, PatternsInOtherUnitsThanTheDrapeAreRefused) {
  const std::string folder = make_sample_folder("flag", 600);
  Garment g = read_garment(folder + "/garment.obj");
  g.P *= 1000.0;
  write_garment(g, folder + "/garment.obj");
  const std::string before = test::read_text(folder + "/garment.obj");
  const auto r = test::run(test::tool_path("drape-free") + " " + folder + "/scene.xml -o " + folder + "/out.obj");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("drape-free: " + folder + "/garment.obj: the drape is 0.001 times the size of its patterns", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/out.obj"));
  EXPECT_EQ(test::read_text(folder + "/garment.obj"), before);
}

// Pins that hold cloth twice its pattern length get a warning that names the edge before the
// solve; the sample's own pins (cloth at rest between them) get none.
TEST(DrapeFree, PinsHoldingTheClothFarFromItsRestShapeAreWarnedOf) {
  const std::string folder = make_sample_folder("flag", 600);
  const std::string out = folder + "/out.obj";
  const auto at_rest = test::run(test::tool_path("drape-free") + " --max-steps 1 " + folder + "/scene.xml -o " + out);
  EXPECT_EQ(at_rest.err.find("warning"), std::string::npos) << at_rest.err;
  Garment g = read_garment(folder + "/garment.obj");
  g.P *= 0.5;  // the drape twice its patterns' size: within the units check, but the pole edge held at 2x
  write_garment(g, folder + "/garment.obj");
  const auto r = test::run(test::tool_path("drape-free") + " --max-steps 1 " + folder + "/scene.xml -o " + out);
  EXPECT_EQ(r.err.rfind("drape-free: warning: " + folder + "/scene.xml: the pins hold the edge v", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(" at 2 times its pattern length"), std::string::npos) << r.err;
}

// A re-drape after the patterns change (--patterns new, --init the drape of the old ones)
// starts from the drape's predicted response to the change, and says so; --no-predictor and
// an unchanged pattern start from the drape as it is.
TEST(DrapeFree, ReDrapeStartsFromThePredictedResponseToThePatternChange) {
  const std::string folder = make_sample_folder("flag", 600);
  const std::string drape = folder + "/drape.obj";
  ASSERT_EQ(test::run(test::tool_path("drape-free") + " " + folder + "/scene.xml -o " + drape).status, 0);
  Garment wider = read_garment(drape);
  wider.P.col(0) *= 1.02;
  write_garment(wider, folder + "/wider.obj");
  const std::string redrape = test::tool_path("drape-free") + " --json " + folder + "/scene.xml --patterns " + folder +
                              "/wider.obj --init " + drape + " -o " + folder + "/redraped.obj";
  expect_report(test::run(redrape),
        "p=d['predictor']; assert d['converged'] and p['applied'] and p['message'] == '' and 0 < p['step_fraction'] <= 1 "
        "and p['largest_move_m'] > 0 and p['time_s'] <= d['time_s']['total'], d");
  expect_report(test::run(redrape + " --no-predictor"), "assert d['converged'] and 'predictor' not in d, d");
  EXPECT_EQ(read_garment(folder + "/redraped.obj").P, wider.P);
  expect_report(test::run(test::tool_path("drape-free") + " --json " + folder + "/scene.xml --init " + drape + " -o " + folder + "/again.obj"),
        "assert d['converged'] and 'predictor' not in d and d['newton_iterations'] == 0, d");
}

// The fast preset on a re-drape stops after its budget of 20 Newton iterations (drape-free
// --help) and writes that drape with exit 0, saying that it is not an equilibrium and how far
// it moved: the committed skirt sample (a drape-free equilibrium, 9880 triangles) with its
// patterns 5 % wider, which the accurate preset takes about 100 iterations to re-drape, and
// again from that drape. On a cold drape the fast preset has no budget: it drapes to its
// residual.
TEST(DrapeFree, FastPresetStopsAReDrapeAtItsBudgetAndWritesIt) {
  const std::string folder = test::temp_folder() + "/fast";
  std::filesystem::create_directories(folder);
  const std::string drape = test::source_path("samples/skirt/garment.obj");
  Garment wider = read_garment(drape);
  wider.P.col(0) *= 1.05;
  write_garment(wider, folder + "/wider.obj");
  const std::string redrape = test::tool_path("drape-free") + " " + test::source_path("samples/skirt/scene.xml") +
                              " --preset fast --patterns " + folder + "/wider.obj --init " + drape + " -o " + folder + "/fast.obj";
  expect_report(test::run(redrape + " --json"),
        "assert d['stopped_at_budget'] and not d['converged'] and d['newton_iterations'] == 20 and d['residual'] > d['tolerance'] "
        "and d['predictor']['applied'] and d['moved_mean_m'] > 1e-4 and d['output'].endswith('fast.obj') "
        "and 'budget of 20 Newton iterations' in d['message'], d");
  const Garment written = read_garment(folder + "/fast.obj");
  EXPECT_EQ(written.P, wider.P);
  EXPECT_TRUE(written.V.allFinite());
  EXPECT_GT((written.V - read_garment(drape).V).norm(), 0.01);
  // The next re-drape of a loop starts from that drape, which is no equilibrium but near one
  // as far as the change can tell: it keeps the budget.
  wider.P.col(0) *= 1.05;
  write_garment(wider, folder + "/wider2.obj");
  expect_report(test::run(test::tool_path("drape-free") + " --json " + test::source_path("samples/skirt/scene.xml") +
                  " --preset fast --patterns " + folder + "/wider2.obj --init " + folder + "/fast.obj -o " + folder + "/fast2.obj"),
        "assert d['stopped_at_budget'] and d['newton_iterations'] == 20, d");
  const auto human = test::run(redrape);
  EXPECT_EQ(human.status, 0) << human.err;
  EXPECT_NE(human.out.find("drape-free: fast preset on a re-drape: stopped at its budget, "), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("not an equilibrium"), std::string::npos) << human.out;
  const std::string flag = make_sample_folder("flag", 600);
  expect_report(test::run(test::tool_path("drape-free") + " --json --preset fast " + flag + "/scene.xml -o " + flag + "/fast.obj"),
        "assert d['converged'] and not d['stopped_at_budget'] and d['newton_iterations'] > 20 and d['residual'] <= 1e-4, d");
}

// --plain-metric, a measurement switch, damps by the plain Laplacian instead of the
// stress-weighted one: the flag drapes to equilibrium both ways, on paths of their own.
TEST(DrapeFree, PlainMetricIsAMeasurementSwitch) {
  const std::string folder = make_sample_folder("flag", 600);
  const std::string converged = "assert d['converged'] and d['residual'] <= 1e-6, d";
  expect_drape(folder, "", converged);
  const Garment weighted = read_garment(folder + "/draped.obj");
  expect_drape(folder, "--plain-metric", converged);
  EXPECT_NE(read_garment(folder + "/draped.obj").V, weighted.V) << "the switch changed nothing";
}

// The scene switch for self-contact reaches the engine: the flag drapes with it on, and the
// report names the term.
TEST(DrapeFree, SelfContactIsASceneSwitch) {
  const std::string folder = make_sample_folder("flag", 600);
  const std::string scene = test::read_text(switched_scene(folder, "self-contact=\"false\"", "self-contact=\"true\"", "self.xml"));
  const auto r = test::run(test::tool_path("drape-free") + " --json " + folder + "/self.xml -o " + folder + "/self.obj");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("\"self_contact\":"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"min_self_distance_m\":"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(folder + "/self.obj"));
  const Garment flag = read_garment(folder + "/garment.obj");
  EXPECT_NE(r.out.find("\"self_contact_vertices\":" + std::to_string(flag.V.rows())), std::string::npos) << r.out;

  // Restricted to a region named in the scene: the vertices in its box, here the flag's lower
  // half (the flag hangs in y).
  const double middle = 0.5 * (flag.V.col(1).minCoeff() + flag.V.col(1).maxCoeff());
  const std::string region = "  <self-contact box=\"-10 -10 -10 10 " + std::to_string(middle) + " 10\"/>\n";
  std::string restricted = scene;
  restricted.insert(restricted.find("  <simulator"), region);
  test::write_text(folder + "/region.xml", restricted);
  const auto q = test::run(test::tool_path("drape-free") + " --json " + folder + "/region.xml -o " + folder + "/region.obj");
  ASSERT_EQ(q.status, 0) << q.err << q.out;
  const long below = (flag.V.col(1).array() <= std::stod(std::to_string(middle))).count();
  ASSERT_GT(below, 0);
  ASSERT_LT(below, flag.V.rows());
  EXPECT_NE(q.out.find("\"self_contact_vertices\":" + std::to_string(below)), std::string::npos) << q.out << " expected " << below;

  // A region naming a vertex the garment does not have: a clear error, nothing written.
  std::string bad = scene;
  bad.insert(bad.find("  <simulator"), "  <self-contact vertices=\"" + std::to_string(flag.V.rows() + 1) + "\"/>\n");
  test::write_text(folder + "/bad.xml", bad);
  const auto b = test::run(test::tool_path("drape-free") + " " + folder + "/bad.xml -o " + folder + "/bad.obj");
  EXPECT_NE(b.status, 0);
  EXPECT_NE(b.err.find("a self-contact region names drape vertex " + std::to_string(flag.V.rows() + 1)), std::string::npos) << b.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/bad.obj"));
}

TEST(DrapeFree, DrapesCoarseToFineAndReportsEveryLevel) {
  const std::string folder = make_sample_folder("flag", 1200);
  expect_drape(folder, "--coarse-levels 300",
               "l=d['levels']; assert d['converged'] and d['residual'] <= 1e-6 and len(l) == 2, d; "
               "assert 200 < l[0]['triangles'] < 400 and l[0]['converged'] and l[1]['residual'] == d['residual'], l; "
               "assert d['time_s']['total'] >= l[0]['time_s'] + l[1]['time_s'], d");

  // Coarse levels cannot carry self-contact: a clear error, nothing written.
  switched_scene(folder, "self-contact=\"false\"", "self-contact=\"true\"", "self.xml");
  const auto b = test::run(test::tool_path("drape-free") + " --coarse-levels 300 " + folder + "/self.xml -o " + folder + "/self.obj");
  EXPECT_EQ(b.status, 1);
  EXPECT_NE(b.err.find(folder + "/self.xml"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("self-contact"), std::string::npos) << b.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/self.obj"));
}

} // namespace
} // namespace foldsketch
