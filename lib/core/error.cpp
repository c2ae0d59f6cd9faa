#include "core/error.h"

namespace foldsketch {
namespace {
std::string located(const std::string& path, int line, const std::string& message) {
  if (line > 0) return path + ":" + std::to_string(line) + ": " + message;
  return path + ": " + message;
}
} // namespace

InputError::InputError(std::string path, int line, const std::string& message)
    : std::runtime_error(located(path, line, message)), path_(std::move(path)), line_(line) {}

} // namespace foldsketch
