#include "mesh/primitive_meshes.h"

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace foldsketch {

TriangleMesh box_mesh(const Vector3d& lo, const Vector3d& hi) {
  TriangleMesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) m.V.row(i) << (i & 1 ? hi.x() : lo.x()), (i & 2 ? hi.y() : lo.y()), (i & 4 ? hi.z() : lo.z());
  m.F.resize(12, 3);
  m.F << 0, 2, 3, 0, 3, 1,   // -z
      4, 5, 7, 4, 7, 6,      // +z
      0, 4, 6, 0, 6, 2,      // -x
      1, 3, 7, 1, 7, 5,      // +x
      0, 1, 5, 0, 5, 4,      // -y
      2, 6, 7, 2, 7, 3;      // +y
  return m;
}

TriangleMesh cylinder_mesh(const Eigen::Vector2d& center, double radius, double y0, double y1, int segments) {
  if (segments < 3 || !(radius > 0.0) || !(y1 > y0)) throw ArgumentError("cylinder_mesh: bad dimensions");
  TriangleMesh m;
  m.V.resize(2 * segments + 2, 3);
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / segments;
    const double x = center.x() + radius * std::cos(a), z = center.y() - radius * std::sin(a);
    m.V.row(i) << x, y0, z;
    m.V.row(segments + i) << x, y1, z;
  }
  m.V.row(2 * segments) << center.x(), y0, center.y();
  m.V.row(2 * segments + 1) << center.x(), y1, center.y();
  m.F.resize(4 * segments, 3);
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    m.F.row(4 * i + 0) << i, j, segments + j;
    m.F.row(4 * i + 1) << i, segments + j, segments + i;
    m.F.row(4 * i + 2) << 2 * segments, j, i;                     // bottom cap, facing -y
    m.F.row(4 * i + 3) << 2 * segments + 1, segments + i, segments + j;  // top cap, facing +y
  }
  return m;
}

} // namespace foldsketch
