#include "scene_xml.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "atomic_file.h"
#include "core/error.h"
#include "text_numbers.h"
#include "xml_util.h"

namespace foldsketch {
namespace {
using tinyxml2::XMLElement;

std::string required(const XMLElement& e, const char* name, const std::string& path) {
  const char* text = e.Attribute(name);
  if (!text || !*text) throw InputError(path, e.GetLineNum(), "<" + std::string(e.Name()) + "> needs a " + name + " attribute");
  return text;
}

std::vector<double> numbers(const XMLElement& e, const char* name, const std::string& path) {
  std::istringstream words(required(e, name, path));
  std::vector<double> out;
  for (std::string w; words >> w;) {
    const auto x = parse_double(w);
    if (!x || !std::isfinite(*x))
      throw InputError(path, e.GetLineNum(), "attribute " + std::string(name) + " of <" + e.Name() + ">: expected a number, found '" + w + "'");
    out.push_back(*x);
  }
  return out;
}

void check_file(const XMLElement& e, const std::string& scene_path, const std::string& file) {
  if (!std::filesystem::exists(scene_relative(scene_path, file)))
    throw InputError(scene_path, e.GetLineNum(), "<" + std::string(e.Name()) + "> names file '" + file + "', which does not exist");
}

Material read_material(const XMLElement& e, const std::string& path) {
  check_attributes(e, path, {"preset", "density", "stretch-warp", "stretch-weft", "shear", "poisson", "bending"});
  Material m;
  if (const char* preset = e.Attribute("preset")) {
    const auto found = material_preset(preset);
    if (!found) {
      std::string known;
      for (const std::string& n : material_preset_names()) known += (known.empty() ? "" : ", ") + n;
      throw InputError(path, e.GetLineNum(), "unknown material preset '" + std::string(preset) + "' (known: " + known + ")");
    }
    m = *found;
  } else {
    m.name = "custom";
    m.source = "scene file";
  }
  m.density = number_attribute(e, "density", path, m.density);
  m.stretch_warp = number_attribute(e, "stretch-warp", path, m.stretch_warp);
  m.stretch_weft = number_attribute(e, "stretch-weft", path, m.stretch_weft);
  m.shear = number_attribute(e, "shear", path, m.shear);
  m.poisson = number_attribute(e, "poisson", path, m.poisson);
  m.bending = number_attribute(e, "bending", path, m.bending);
  if (const std::string error = material_error(m); !error.empty()) throw InputError(path, e.GetLineNum(), "material: " + error);
  return m;
}

// <pin> or <self-contact>: a box and/or 1-based vertex numbers.
VertexSelector read_selector(const XMLElement& e, const std::string& path) {
  const std::string tag = e.Name();
  check_attributes(e, path, {"box", "vertices"});
  VertexSelector selector;
  if (e.Attribute("box")) {
    const std::vector<double> b = numbers(e, "box", path);
    if (b.size() != 6 || b[0] > b[3] || b[1] > b[4] || b[2] > b[5])
      throw InputError(path, e.GetLineNum(), "<" + tag + " box> needs 'xmin ymin zmin xmax ymax zmax' with min <= max [m]");
    selector.box = Eigen::AlignedBox3d(Vector3d(b[0], b[1], b[2]), Vector3d(b[3], b[4], b[5]));
  }
  if (e.Attribute("vertices")) {
    std::istringstream words(e.Attribute("vertices"));
    for (std::string w; words >> w;) {
      const auto i = parse_integer(w);
      if (!i || *i < 1 || *i > (1LL << 30))
        throw InputError(path, e.GetLineNum(), "<" + tag + " vertices>: expected 1-based drape vertex numbers, found '" + w + "'");
      selector.vertices.push_back(static_cast<int>(*i) - 1);
    }
  }
  if (!selector.box && selector.vertices.empty()) throw InputError(path, e.GetLineNum(), "<" + tag + "> needs a box or vertices attribute");
  return selector;
}

SimulatorSettings read_simulator(const XMLElement& e, const std::string& path) {
  check_attributes(e, path, {"mode", "preset", "time-step", "max-steps", "tolerance"});
  SimulatorSettings s;
  if (const char* mode = e.Attribute("mode")) {
    if (std::string(mode) == "static") s.mode = SimulationMode::Static;
    else if (std::string(mode) == "dynamic") s.mode = SimulationMode::Dynamic;
    else throw InputError(path, e.GetLineNum(), "unknown simulator mode '" + std::string(mode) + "' (known: static, dynamic)");
  }
  if (const char* preset = e.Attribute("preset")) {
    if (std::string(preset) == "accurate") s.preset = SolverPreset::Accurate;
    else if (std::string(preset) == "fast") s.preset = SolverPreset::Fast;
    else throw InputError(path, e.GetLineNum(), "unknown solver preset '" + std::string(preset) + "' (known: accurate, fast)");
  }
  s.time_step = number_attribute(e, "time-step", path, s.time_step);
  const double steps = number_attribute(e, "max-steps", path, s.max_steps);
  s.tolerance = number_attribute(e, "tolerance", path, s.tolerance);
  if (!(s.time_step > 0.0)) throw InputError(path, e.GetLineNum(), "time-step must be positive [s]");
  if (!(steps >= 1.0) || steps != std::floor(steps) || steps > 1e9) throw InputError(path, e.GetLineNum(), "max-steps must be a positive whole number");
  s.max_steps = static_cast<int>(steps);
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0)) throw InputError(path, e.GetLineNum(), "tolerance must be in (0, 1)");
  return s;
}

} // namespace

std::string scene_relative(const std::string& scene_path, const std::string& file) {
  const std::filesystem::path f(file);
  if (f.is_absolute()) return file;
  return (std::filesystem::path(scene_path).parent_path() / f).lexically_normal().string();
}

Scene read_scene_xml(const std::string& path) {
  tinyxml2::XMLDocument doc;
  load_xml(doc, path);
  const XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "scene") throw InputError(path, root ? root->GetLineNum() : 1, "expected a <scene> root element");
  check_attributes(*root, path, {"name"});
  Scene scene;
  scene.name = root->Attribute("name") ? root->Attribute("name") : std::filesystem::path(path).parent_path().filename().string();
  bool have_material = false;
  int first_region_line = 0;
  for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "garment") {
      check_attributes(*e, path, {"file"});
      scene.garment_file = required(*e, "file", path);
      check_file(*e, path, scene.garment_file);
    } else if (tag == "body") {
      check_attributes(*e, path, {"file", "thickness"});
      BodySettings body;
      body.file = required(*e, "file", path);
      body.thickness = number_attribute(*e, "thickness", path, body.thickness);
      if (!(body.thickness >= 0.0)) throw InputError(path, e->GetLineNum(), "body thickness must be >= 0 [m]");
      check_file(*e, path, body.file);
      scene.body = body;
    } else if (tag == "material") {
      scene.material = read_material(*e, path);
      have_material = true;
    } else if (tag == "gravity") {
      check_attributes(*e, path, {"x", "y", "z"});
      scene.gravity = {number_attribute(*e, "x", path, 0.0), number_attribute(*e, "y", path, 0.0), number_attribute(*e, "z", path, 0.0)};
    } else if (tag == "physics") {
      check_attributes(*e, path, {"body-contact", "self-contact", "friction", "hemline"});
      PhysicsSwitches& p = scene.physics;
      p.body_contact = bool_attribute(*e, "body-contact", path, p.body_contact);
      p.self_contact = bool_attribute(*e, "self-contact", path, p.self_contact);
      p.friction = bool_attribute(*e, "friction", path, p.friction);
      p.hemline = bool_attribute(*e, "hemline", path, p.hemline);
    } else if (tag == "pin") {
      scene.pins.push_back(read_selector(*e, path));
    } else if (tag == "self-contact") {
      if (scene.self_contact_regions.empty()) first_region_line = e->GetLineNum();
      scene.self_contact_regions.push_back(read_selector(*e, path));
    } else if (tag == "simulator") {
      scene.simulator = read_simulator(*e, path);
    } else {
      throw InputError(path, e->GetLineNum(),
                       "unknown element <" + tag + "> (known: garment, body, material, gravity, physics, pin, self-contact, simulator)");
    }
  }
  if (scene.garment_file.empty()) throw InputError(path, root->GetLineNum(), "the scene names no <garment file=...>");
  if (!have_material) throw InputError(path, root->GetLineNum(), "the scene names no <material>");
  if (!scene.self_contact_regions.empty() && !scene.physics.self_contact)
    throw InputError(path, first_region_line, "<self-contact> gives a region but self-contact is off (<physics self-contact=\"true\"/>)");
  if (!scene.body && (scene.physics.body_contact || scene.physics.friction))
    throw InputError(path, root->GetLineNum(), "body contact is on but the scene names no <body file=...>");
  return scene;
}

std::string scene_xml_text(const Scene& s) {
  const auto b = [](bool x) { return x ? "true" : "false"; };
  std::string t = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- foldsketch scene; SI units: m, kg, s. Files are relative to this one. -->\n";
  t += "<scene name=\"" + xml_escaped(s.name) + "\">\n";
  t += "  <garment file=\"" + xml_escaped(s.garment_file) + "\"/>\n";
  if (s.body) t += "  <body file=\"" + xml_escaped(s.body->file) + "\" thickness=\"" + format_double(s.body->thickness) + "\"/>\n";
  const Material& m = s.material;
  const auto preset = material_preset(m.name);
  if (preset && preset->density == m.density && preset->stretch_warp == m.stretch_warp && preset->stretch_weft == m.stretch_weft &&
      preset->shear == m.shear && preset->poisson == m.poisson && preset->bending == m.bending) {
    t += "  <material preset=\"" + m.name + "\"/>\n";
  } else {
    t += "  <material density=\"" + format_double(m.density) + "\" stretch-warp=\"" + format_double(m.stretch_warp) +
         "\" stretch-weft=\"" + format_double(m.stretch_weft) + "\" shear=\"" + format_double(m.shear) + "\" poisson=\"" +
         format_double(m.poisson) + "\" bending=\"" + format_double(m.bending) + "\"/>\n";
  }
  t += "  <gravity x=\"" + format_double(s.gravity.x()) + "\" y=\"" + format_double(s.gravity.y()) + "\" z=\"" + format_double(s.gravity.z()) + "\"/>\n";
  t += std::string("  <physics body-contact=\"") + b(s.physics.body_contact) + "\" self-contact=\"" + b(s.physics.self_contact) +
       "\" friction=\"" + b(s.physics.friction) + "\" hemline=\"" + b(s.physics.hemline) + "\"/>\n";
  const auto selectors = [&](const std::vector<VertexSelector>& list, const char* tag) {
    for (const VertexSelector& p : list) {
      t += std::string("  <") + tag;
      if (p.box) {
        const Vector3d lo = p.box->min(), hi = p.box->max();
        t += " box=\"" + format_double(lo.x()) + ' ' + format_double(lo.y()) + ' ' + format_double(lo.z()) + ' ' +
             format_double(hi.x()) + ' ' + format_double(hi.y()) + ' ' + format_double(hi.z()) + "\"";
      }
      if (!p.vertices.empty()) {
        t += " vertices=\"";
        for (size_t i = 0; i < p.vertices.size(); ++i) t += (i ? " " : "") + std::to_string(p.vertices[i] + 1);
        t += "\"";
      }
      t += "/>\n";
    }
  };
  selectors(s.pins, "pin");
  selectors(s.self_contact_regions, "self-contact");
  const SimulatorSettings& sim = s.simulator;
  t += std::string("  <simulator mode=\"") + to_string(sim.mode) + "\" preset=\"" + to_string(sim.preset) + "\" time-step=\"" +
       format_double(sim.time_step) + "\" max-steps=\"" + std::to_string(sim.max_steps) + "\" tolerance=\"" +
       format_double(sim.tolerance) + "\"/>\n";
  t += "</scene>\n";
  return t;
}

void write_scene_xml(const Scene& scene, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { out << scene_xml_text(scene); });
}

} // namespace foldsketch
