// A whole file read into memory, for the readers that parse from a buffer.
#pragma once

#include <string>

namespace foldsketch {

// The bytes of the file at `path`; throws InputError "path: no such file" or "path: cannot open
// for reading".
std::string read_text_file(const std::string& path);

} // namespace foldsketch
