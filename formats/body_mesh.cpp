#include "body_mesh.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "atomic_file.h"
#include "body_obj.h"
#include "text_file.h"
#include "core/error.h"
#include "text_numbers.h"

namespace foldsketch {

namespace {

bool has_obj_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".obj";
}

} // namespace

TriangleMesh read_body_mesh(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, 0, "no such file");
  if (has_obj_extension(path)) {
    if (std::optional<TriangleMesh> mesh = parse_body_obj(read_text_file(path), path)) return std::move(*mesh);
  }
  Assimp::Importer importer;
  // Drop normals, texture coordinates and colours before welding, so vertices at the same
  // position weld even where the file splits them for shading.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                                          aiComponent_COLORS | aiComponent_TEXCOORDS |
                                                          aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                                                          aiComponent_TEXTURES | aiComponent_LIGHTS |
                                                          aiComponent_CAMERAS | aiComponent_MATERIALS);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw InputError(path, 0, std::string("cannot read mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  int vertices = 0, triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertices += static_cast<int>(scene->mMeshes[m]->mNumVertices);
    for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f) triangles += scene->mMeshes[m]->mFaces[f].mNumIndices == 3;
  }
  if (triangles == 0) throw InputError(path, 0, "the mesh has no triangles");
  mesh.V.resize(vertices, 3);
  mesh.F.resize(triangles, 3);
  int v0 = 0, t = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* a = scene->mMeshes[m];
    for (unsigned v = 0; v < a->mNumVertices; ++v) {
      mesh.V.row(v0 + static_cast<int>(v)) << a->mVertices[v].x, a->mVertices[v].y, a->mVertices[v].z;
      if (!mesh.V.row(v0 + static_cast<int>(v)).allFinite())
        throw InputError(path, 0, "vertex " + std::to_string(v0 + v + 1) + " has a NaN or Inf coordinate");
    }
    for (unsigned f = 0; f < a->mNumFaces; ++f)
      if (a->mFaces[f].mNumIndices == 3)
        mesh.F.row(t++) << v0 + static_cast<int>(a->mFaces[f].mIndices[0]), v0 + static_cast<int>(a->mFaces[f].mIndices[1]),
            v0 + static_cast<int>(a->mFaces[f].mIndices[2]);
    v0 += static_cast<int>(a->mNumVertices);
  }
  return mesh;
}

void write_mesh_obj(const TriangleMesh& mesh, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    std::string text = "# foldsketch mesh [m]\n";
    for (int i = 0; i < mesh.V.rows(); ++i)
      text += "v " + format_double(mesh.V(i, 0)) + ' ' + format_double(mesh.V(i, 1)) + ' ' + format_double(mesh.V(i, 2)) + '\n';
    for (int f = 0; f < mesh.F.rows(); ++f)
      text += "f " + std::to_string(mesh.F(f, 0) + 1) + ' ' + std::to_string(mesh.F(f, 1) + 1) + ' ' + std::to_string(mesh.F(f, 2) + 1) + '\n';
    out << text;
  });
}

} // namespace foldsketch
