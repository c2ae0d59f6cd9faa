#include "json_writer.h"

#include <cmath>
#include <cstdio>

#include "text_numbers.h"

namespace foldsketch {

void JsonWriter::separate() {
  if (after_key_) { after_key_ = false; return; }
  if (!first_.empty()) {
    if (!first_.back()) text_ += ',';
    first_.back() = false;
  }
}

JsonWriter& JsonWriter::begin_object() { separate(); text_ += '{'; first_.push_back(true); return *this; }
JsonWriter& JsonWriter::end_object() { text_ += '}'; first_.pop_back(); return *this; }
JsonWriter& JsonWriter::begin_array() { separate(); text_ += '['; first_.push_back(true); return *this; }
JsonWriter& JsonWriter::end_array() { text_ += ']'; first_.pop_back(); return *this; }

JsonWriter& JsonWriter::key(const std::string& name) {
  value(name);
  text_ += ':';
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& s) {
  separate();
  text_ += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': text_ += "\\\""; break;
      case '\\': text_ += "\\\\"; break;
      case '\n': text_ += "\\n"; break;
      case '\r': text_ += "\\r"; break;
      case '\t': text_ += "\\t"; break;
      default:
        if (c < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          text_ += buffer;
        } else {
          text_ += static_cast<char>(c);
        }
    }
  }
  text_ += '"';
  return *this;
}

JsonWriter& JsonWriter::value(double x) {
  if (!std::isfinite(x)) return null();
  separate();
  text_ += format_double(x);
  return *this;
}

JsonWriter& JsonWriter::value(long long x) { separate(); text_ += std::to_string(x); return *this; }
JsonWriter& JsonWriter::value(bool b) { separate(); text_ += b ? "true" : "false"; return *this; }
JsonWriter& JsonWriter::null() { separate(); text_ += "null"; return *this; }

} // namespace foldsketch
