// Writing output files so that a reader (or make) never sees a half-written file: write a
// temporary file in the same folder, then rename it over the target on success.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace foldsketch {

// Calls write(stream) on a temporary file next to `path` and renames it to `path` if write
// returns without throwing and every byte reached the disk. On failure the temporary file is
// removed, `path` is left as it was, and the exception propagates (an InputError naming path
// for I/O failures). path "-" writes to standard output.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

} // namespace foldsketch
