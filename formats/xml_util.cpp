#include "xml_util.h"

#include <cmath>

#include "core/error.h"
#include "text_file.h"
#include "text_numbers.h"

namespace foldsketch {

void load_xml(tinyxml2::XMLDocument& doc, const std::string& path) {
  const std::string s = read_text_file(path);
  if (doc.Parse(s.data(), s.size()) != tinyxml2::XML_SUCCESS) {
    // tinyxml2's ErrorStr() reads "Error=NAME ErrorID=N (0xN) Line number=L[: detail]"; keep
    // the detail, or say plainly what the error name means.
    const std::string full = doc.ErrorStr();
    const auto colon = full.find(": ");
    std::string detail = colon != std::string::npos ? full.substr(colon + 2) : std::string(doc.ErrorName());
    switch (doc.ErrorID()) {
      case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: detail = "the file is empty"; break;
      case tinyxml2::XML_ERROR_PARSING_ELEMENT: detail = "an element is not closed (missing '>' or '/>'?)"; break;
      case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE: detail = "bad attribute (missing '=' or quotes?)"; break;
      case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT: detail = "a closing tag does not match its opening tag"; break;
      default: break;
    }
    throw InputError(path, doc.ErrorLineNum(), "malformed XML: " + detail);
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
