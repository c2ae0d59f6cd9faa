// A small streaming JSON writer for the tools' --json summaries (one line, exact numbers).
#pragma once

#include <string>
#include <vector>

namespace foldsketch {

class JsonWriter {
public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(const std::string& name);
  JsonWriter& value(const std::string& s);
  JsonWriter& value(const char* s) { return value(std::string(s)); }
  JsonWriter& value(double x);   // NaN and Inf are written as null (JSON has no spelling)
  JsonWriter& value(long long x);
  JsonWriter& value(int x) { return value(static_cast<long long>(x)); }
  JsonWriter& value(size_t x) { return value(static_cast<long long>(x)); }
  JsonWriter& value(bool b);
  JsonWriter& null();
  const std::string& str() const { return text_; }

private:
  void separate();
  std::string text_;
  std::vector<bool> first_;  // per open container: nothing written in it yet
  bool after_key_ = false;
};

} // namespace foldsketch
