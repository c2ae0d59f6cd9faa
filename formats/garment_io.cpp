#include "garment_io.h"

#include <filesystem>

#include "atomic_file.h"
#include "core/error.h"
#include "garment_obj.h"
#include "stitches_xml.h"

namespace foldsketch {

std::string stitches_path(const std::string& garment_path) {
  std::filesystem::path p(garment_path);
  p.replace_extension(".stitches.xml");
  return p.string();
}

Garment read_garment(const std::string& path) {
  Garment g = read_garment_obj(path);
  const std::string sidecar = stitches_path(path);
  if (std::filesystem::exists(sidecar)) {
    for (const LocatedStitch& s : read_stitches_xml(sidecar)) {
      for (const StitchPoint* p : {&s.stitch.a, &s.stitch.b})
        for (int v : {p->v0, p->v1})
          if (v >= g.V.rows())
            throw InputError(sidecar, s.line, "stitch names drape vertex " + std::to_string(v + 1) + " but " + path + " has " +
                                                  std::to_string(g.V.rows()));
      g.stitches.push_back(s.stitch);
    }
  }
  return g;
}

void write_garment(const Garment& g, const std::string& path) {
  if (const std::string error = garment_structure_error(g); !error.empty())
    throw ArgumentError("write_garment: " + error);
  if (path != "-") {
    const std::string sidecar = stitches_path(path);
    if (!g.stitches.empty()) {
      write_file_atomically(sidecar, [&](std::ostream& out) { out << stitches_xml_text(g.stitches); });
    } else {
      std::error_code ignored;
      std::filesystem::remove(sidecar, ignored);
    }
  }
  write_file_atomically(path, [&](std::ostream& out) { print_garment_obj(g, out); });
}

} // namespace foldsketch
