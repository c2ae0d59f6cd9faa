#include "text_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace foldsketch {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::filesystem::exists(path) ? "cannot open for reading" : "no such file");
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

} // namespace foldsketch
