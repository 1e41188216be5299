#include "mesh_loader.hpp"

#include <acd/io.hpp>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>

namespace planner {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

LoadedMesh viaAssimp(const std::string& path) {
  LoadedMesh out;
  Assimp::Importer importer;
  // Coordinates as written in the file: no turning of Z_UP scenes into assimp's Y-up.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode) {
    out.error = path + ": cannot read (" + importer.GetErrorString() + ")";
    return out;
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int base = static_cast<int>(out.mesh.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      out.mesh.vertices.emplace_back(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left over by triangulation
      out.mesh.faces.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                base + static_cast<int>(face.mIndices[2])});
    }
  }
  if (out.mesh.empty()) {
    out.error = path + ": no triangles";
    return out;
  }
  out.ok = true;
  return out;
}

}  // namespace

LoadedMesh loadMeshFile(const std::string& path) {
  LoadedMesh out;
  if (!std::filesystem::exists(path)) {
    out.error = path + ": file not found";
    return out;
  }
  const std::string ext = lowerExtension(path);
  if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl") {
    acd::ReadResult r = acd::readMesh(path);
    if (!r.status.ok()) {
      out.error = r.status.message;
      return out;
    }
    out.ok = true;
    out.mesh = std::move(r.mesh);
    return out;
  }
  return viaAssimp(path);
}

}  // namespace planner
