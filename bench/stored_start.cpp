#include "stored_start.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "formats/atomic_file.h"

namespace foldsketch {
namespace {
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull, kFnvPrime = 1099511628211ull;  // FNV-1a, 64 bit

template <typename Matrix>
void hash_bytes(std::uint64_t& h, const Matrix& m) {
  // Row-major order, so the hash does not depend on Eigen's storage order.
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      const auto value = m(r, c);
      unsigned char bytes[sizeof value];
      std::memcpy(bytes, &value, sizeof value);
      for (const unsigned char b : bytes) h = (h ^ b) * kFnvPrime;
    }
}

constexpr const char* kFingerprintComment = "comment foldsketch-rest-mesh ";

// The fingerprint as the header writes it: 16 hex digits.
std::string fingerprint_hex(std::uint64_t fingerprint) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fingerprint));
  return hex;
}
}  // namespace

std::string stored_start_path(const std::string& folder, long triangles, int k) {
  return folder + "/skirt-" + std::to_string(triangles) + "-" + std::to_string(k) + ".ply";
}

std::uint64_t mesh_fingerprint(const Garment& g) {
  std::uint64_t h = kFnvOffset;
  hash_bytes(h, g.F);
  hash_bytes(h, g.FP);
  hash_bytes(h, g.P);
  hash_bytes(h, g.V);
  return h;
}

void write_stored_start(const std::string& path, const MatrixX3d& x, std::uint64_t fingerprint, const std::string& comment) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment " << comment << '\n'
        << kFingerprintComment << fingerprint_hex(fingerprint) << "\nelement vertex " << x.rows()
        << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    for (Eigen::Index v = 0; v < x.rows(); ++v)
      for (int c = 0; c < 3; ++c) {
        const auto f = static_cast<float>(x(v, c));
        out.write(reinterpret_cast<const char*>(&f), sizeof f);  // x86: little-endian already
      }
  });
}

MatrixX3d read_stored_start(const std::string& path, Eigen::Index vertices, std::uint64_t fingerprint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the stored start");
  std::string line;
  int line_number = 0;
  Eigen::Index count = -1;
  bool fingerprint_seen = false;
  int properties = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 && line != "ply") throw InputError(path, 1, "not a PLY file (no 'ply' line)");
    if (line == "end_header") break;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format" && line != "format binary_little_endian 1.0")
      throw InputError(path, line_number, "expected 'format binary_little_endian 1.0', found '" + line + "'");
    if (line.rfind(kFingerprintComment, 0) == 0) {
      const std::string found = line.substr(std::strlen(kFingerprintComment)), hex = fingerprint_hex(fingerprint);
      if (found != hex)
        throw InputError(path, line_number,
                         "the start belongs to another mesh (fingerprint " + found + ", this mesh's " + hex +
                             "): write the starts again with drape_bench --write-starts");
      fingerprint_seen = true;
    }
    if (keyword == "element") {
      std::string name;
      words >> name >> count;
      if (name != "vertex" || !words) throw InputError(path, line_number, "expected 'element vertex N', found '" + line + "'");
    }
    if (keyword == "property") {
      static const char* const expected[] = {"property float x", "property float y", "property float z"};
      if (properties >= 3 || line != expected[properties])
        throw InputError(path, line_number, "expected float x, y, z vertex properties, found '" + line + "'");
      ++properties;
    }
  }
  if (line != "end_header") throw InputError(path, line_number, "the header has no end_header");
  if (!fingerprint_seen) throw InputError(path, line_number, "the header has no foldsketch-rest-mesh fingerprint");
  if (properties != 3) throw InputError(path, line_number, "expected float x, y, z vertex properties");
  if (count != vertices)
    throw InputError(path, line_number,
                     "the start has " + std::to_string(count) + " vertices, the mesh " + std::to_string(vertices));
  MatrixX3d x(vertices, 3);
  for (Eigen::Index v = 0; v < vertices; ++v)
    for (int c = 0; c < 3; ++c) {
      float f;
      if (!in.read(reinterpret_cast<char*>(&f), sizeof f))
        throw InputError(path, line_number, "the file ends after " + std::to_string(v) + " of " + std::to_string(vertices) + " vertices");
      if (!std::isfinite(f)) throw InputError(path, line_number, "vertex " + std::to_string(v) + " is not finite");
      x(v, c) = f;
    }
  if (in.peek() != std::char_traits<char>::eof()) throw InputError(path, line_number, "bytes after the last vertex");
  return x;
}

}  // namespace foldsketch
