// Helpers shared by the XML readers: located errors and typed attributes.
#pragma once

#include <initializer_list>
#include <string>

#include <tinyxml2.h>

namespace foldsketch {

// Parse the file at `path` into doc; throws InputError "path:line: ..." for missing files and
// malformed XML.
void load_xml(tinyxml2::XMLDocument& doc, const std::string& path);

// Throws InputError at the element's line if it has an attribute not in `allowed`.
void check_attributes(const tinyxml2::XMLElement& e, const std::string& path, std::initializer_list<const char*> allowed);

// The attribute as a finite number, or `fallback` when absent; throws when malformed.
double number_attribute(const tinyxml2::XMLElement& e, const char* name, const std::string& path, double fallback);
// The attribute as true/false, or `fallback` when absent.
bool bool_attribute(const tinyxml2::XMLElement& e, const char* name, const std::string& path, bool fallback);

// s with &, <, > and quotes escaped for an attribute value.
std::string xml_escaped(const std::string& s);

} // namespace foldsketch
