// Errors thrown by foldsketch library and format code. Library code never prints or exits:
// it throws, and one function in the CLI layer turns the exception into one stderr line.
#pragma once

#include <stdexcept>
#include <string>

namespace foldsketch {

// A problem with an input file or value, located as precisely as the reader knows:
// what() reads "path:line: message", or "path: message" when line is 0.
class InputError : public std::runtime_error {
public:
  InputError(std::string path, int line, const std::string& message);
  const std::string& path() const { return path_; }
  int line() const { return line_; }

private:
  std::string path_;
  int line_;
};

// A violated precondition of a library call (bad sizes, indices out of range): a bug in the
// caller, not in a user's file.
class ArgumentError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

} // namespace foldsketch
