#include "xml_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "text_numbers.h"

namespace foldsketch {

void load_xml(tinyxml2::XMLDocument& doc, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::filesystem::exists(path) ? "cannot open for reading" : "no such file");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  if (doc.Parse(s.data(), s.size()) != tinyxml2::XML_SUCCESS) {
    std::string message = doc.ErrorStr();
    // tinyxml2 prefixes its own "Error=... ErrorID=... Line number=N:" noise; keep the detail.
    if (const auto colon = message.rfind(": "); colon != std::string::npos) message = message.substr(colon + 2);
    throw InputError(path, doc.ErrorLineNum(), "malformed XML (" + std::string(doc.ErrorName()) + "): " + message);
  }
}

void check_attributes(const tinyxml2::XMLElement& e, const std::string& path, std::initializer_list<const char*> allowed) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    bool known = false;
    for (const char* name : allowed) known = known || std::string(name) == a->Name();
    if (!known) {
      std::string list;
      for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      throw InputError(path, e.GetLineNum(), "unknown attribute '" + std::string(a->Name()) + "' on <" + e.Name() + ">" +
                                                 (list.empty() ? "" : " (known: " + list + ")"));
    }
  }
}

double number_attribute(const tinyxml2::XMLElement& e, const char* name, const std::string& path, double fallback) {
  const char* text = e.Attribute(name);
  if (!text) return fallback;
  const auto x = parse_double(text);
  if (!x || !std::isfinite(*x))
    throw InputError(path, e.GetLineNum(), "attribute " + std::string(name) + " of <" + e.Name() + ">: expected a number, found '" + text + "'");
  return *x;
}

bool bool_attribute(const tinyxml2::XMLElement& e, const char* name, const std::string& path, bool fallback) {
  const char* text = e.Attribute(name);
  if (!text) return fallback;
  const std::string s(text);
  if (s == "true" || s == "1" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "no") return false;
  throw InputError(path, e.GetLineNum(), "attribute " + std::string(name) + " of <" + e.Name() + ">: expected true or false, found '" + s + "'");
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

} // namespace foldsketch
