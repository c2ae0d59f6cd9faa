#include "body_obj.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "text_numbers.h"

namespace foldsketch {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Splits one line into blank-separated tokens, in place.
class Tokens {
public:
  explicit Tokens(std::string_view line) : line_(line) {}
  std::string_view next() {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    const size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_])) ++pos_;
    return line_.substr(start, pos_ - start);
  }

private:
  std::string_view line_;
  size_t pos_ = 0;
};

struct RawFace {
  std::array<long long, 4> v;  // 0-based position indices, checked once all v lines are read
  int corners;                 // 3 or 4
  int line;
};

using Position = std::array<float, 3>;

struct PositionHash {
  size_t operator()(const Position& p) const {
    uint64_t h = 1469598103934665603ull;
    for (float x : p) {
      uint32_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return static_cast<size_t>(h);
  }
};

// The corner at which a quadrilateral's two other diagonal triangles fold over, or 0: the
// corner whose angle exceeds pi, as assimp's TriangulateProcess picks it, so both readers cut a
// concave quadrilateral along the same diagonal.
int reflex_corner(const std::array<Eigen::Vector3d, 4>& q) {
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d left = (q[(i + 3) % 4] - q[i]).normalized();
    const Eigen::Vector3d diagonal = (q[(i + 2) % 4] - q[i]).normalized();
    const Eigen::Vector3d right = (q[(i + 1) % 4] - q[i]).normalized();
    const double angle = std::acos(std::clamp(left.dot(diagonal), -1.0, 1.0)) +
                         std::acos(std::clamp(right.dot(diagonal), -1.0, 1.0));
    if (angle > M_PI) return i;
  }
  return 0;
}

} // namespace

std::optional<TriangleMesh> parse_body_obj(std::string_view text, const std::string& path) {
  std::vector<Position> positions;
  std::vector<RawFace> faces;
  int line_number = 0;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    ++line_number;
    Tokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
      Position p;
      for (float& x : p) {
        const std::optional<double> value = parse_double(tokens.next());
        if (!value) throw InputError(path, line_number, "a vertex needs three numbers (x y z)");
        x = static_cast<float>(*value);
        if (!std::isfinite(x))
          throw InputError(path, line_number,
                           "vertex " + std::to_string(positions.size() + 1) + " has a NaN or Inf coordinate");
        x += 0.0f;  // -0 and +0 weld
      }
      positions.push_back(p);
    } else if (keyword == "f") {
      RawFace face{{}, 0, line_number};
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        if (token.front() == '#') break;
        if (face.corners == 4) return std::nullopt;  // a polygon: assimp triangulates those
        const std::optional<long long> index = parse_integer(token.substr(0, token.find('/')));
        if (!index || *index == 0) throw InputError(path, line_number, "'" + std::string(token) + "' is not a vertex index");
        // Negative indices count back from the last v line read so far.
        face.v[face.corners++] = *index > 0 ? *index - 1 : static_cast<long long>(positions.size()) + *index;
      }
      if (face.corners < 3) throw InputError(path, line_number, "a face needs at least three vertices");
      faces.push_back(face);
    }
  }
  if (faces.empty()) throw InputError(path, 0, "the mesh has no triangles");

  // Weld by position, numbering vertices in the order the faces first use them.
  std::unordered_map<Position, int, PositionHash> welded;
  welded.reserve(positions.size());
  std::vector<Position> vertices;
  vertices.reserve(positions.size());
  std::vector<std::array<int, 4>> face_vertices(faces.size());
  int triangles = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const RawFace& face = faces[f];
    for (int c = 0; c < face.corners; ++c) {
      const long long p = face.v[c];
      if (p < 0 || p >= static_cast<long long>(positions.size()))
        throw InputError(path, face.line,
                         "vertex index " + std::to_string(p < 0 ? p - static_cast<long long>(positions.size()) : p + 1) +
                             " is out of range (" + std::to_string(positions.size()) + " vertices)");
      const auto [it, inserted] = welded.try_emplace(positions[p], static_cast<int>(vertices.size()));
      if (inserted) vertices.push_back(positions[p]);
      face_vertices[f][c] = it->second;
    }
    triangles += face.corners - 2;
  }

  TriangleMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i)
    mesh.V.row(static_cast<Eigen::Index>(i)) << vertices[i][0], vertices[i][1], vertices[i][2];
  mesh.F.resize(triangles, 3);
  int t = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::array<int, 4>& v = face_vertices[f];
    if (faces[f].corners == 3) {
      mesh.F.row(t++) << v[0], v[1], v[2];
      continue;
    }
    std::array<Eigen::Vector3d, 4> quad;
    for (int c = 0; c < 4; ++c) quad[c] = mesh.V.row(v[c]).transpose();
    const int s = reflex_corner(quad);
    mesh.F.row(t++) << v[s], v[(s + 1) % 4], v[(s + 2) % 4];
    mesh.F.row(t++) << v[s], v[(s + 2) % 4], v[(s + 3) % 4];
  }
  return mesh;
}

} // namespace foldsketch
