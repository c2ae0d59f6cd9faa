#include "stitches_xml.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "text_numbers.h"
#include "xml_util.h"

namespace foldsketch {
namespace {

StitchPoint parse_point(const tinyxml2::XMLElement& e, const char* name, const std::string& path) {
  const char* text = e.Attribute(name);
  const auto fail = [&](const std::string& why) -> StitchPoint {
    throw InputError(path, e.GetLineNum(), "attribute " + std::string(name) + " of <stitch>: " + why);
  };
  if (!text) return fail("missing (a drape vertex 'V' or an edge point 'V0 V1 T')");
  std::istringstream words(text);
  std::vector<std::string> tokens;
  for (std::string w; words >> w;) tokens.push_back(w);
  if (tokens.size() != 1 && tokens.size() != 3) return fail("expected 'V' or 'V0 V1 T', found '" + std::string(text) + "'");
  StitchPoint p;
  const auto vertex = [&](const std::string& token) {
    const auto i = parse_integer(token);
    if (!i || *i < 1 || *i > (1LL << 30)) fail("expected a 1-based vertex number, found '" + token + "'");
    return static_cast<int>(*i) - 1;
  };
  p.v0 = vertex(tokens[0]);
  if (tokens.size() == 3) {
    p.v1 = vertex(tokens[1]);
    const auto t = parse_double(tokens[2]);
    if (!t || !std::isfinite(*t) || *t < 0.0 || *t > 1.0) fail("expected T in [0, 1], found '" + tokens[2] + "'");
    p.t = *t;
  }
  return p;
}

std::string point_text(const StitchPoint& p) {
  if (p.v1 < 0) return std::to_string(p.v0 + 1);
  return std::to_string(p.v0 + 1) + ' ' + std::to_string(p.v1 + 1) + ' ' + format_double(p.t);
}

} // namespace

std::vector<LocatedStitch> read_stitches_xml(const std::string& path) {
  tinyxml2::XMLDocument doc;
  load_xml(doc, path);
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "stitches")
    throw InputError(path, root ? root->GetLineNum() : 1, "expected a <stitches> root element");
  check_attributes(*root, path, {"version"});
  std::vector<LocatedStitch> out;
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::string(e->Name()) != "stitch")
      throw InputError(path, e->GetLineNum(), "unknown element <" + std::string(e->Name()) + "> in <stitches>");
    check_attributes(*e, path, {"a", "b"});
    out.push_back({{parse_point(*e, "a", path), parse_point(*e, "b", path)}, e->GetLineNum()});
  }
  return out;
}

std::string stitches_xml_text(const std::vector<Stitch>& stitches) {
  std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<!-- foldsketch stitches: drape vertex numbers as in the OBJ (1-based); 'V0 V1 T' is the point\n"
                     "     (1-T) V0 + T V1 on an edge -->\n"
                     "<stitches version=\"1\">\n";
  for (const Stitch& s : stitches) text += "  <stitch a=\"" + point_text(s.a) + "\" b=\"" + point_text(s.b) + "\"/>\n";
  text += "</stitches>\n";
  return text;
}

} // namespace foldsketch
