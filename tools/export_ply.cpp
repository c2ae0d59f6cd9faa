// export-ply: a garment's drape as a PLY coloured by panel, for MeshLab, Blender and friends.
#include "cli.h"
#include "formats/garment_io.h"
#include "formats/garment_ply.h"

int main(int argc, char** argv) {
  using namespace foldsketch;
  CLI::App app{"Reads a garment OBJ (v = drape, vt = pattern, metres) and writes its drape as an ASCII PLY\n"
               "with one colour per panel (positions in metres). Seam vertices are repeated per panel.",
               "export-ply"};
  std::string input, output;
  app.add_option("garment", input, "garment OBJ")->required();
  app.add_option("-o,--output", output, "PLY to write ('-' = standard output)")->required();
  return run_tool(app, argc, argv, [&] { write_garment_ply(read_garment(input), output); });
}
