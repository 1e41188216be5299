#include "ompl_app_import.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace planner {

namespace {

void collect(const aiScene* scene, const aiNode* node, aiMatrix4x4 transform, OmplAppImport& out, acd::Vec3& sum,
             long& count) {
  transform *= node->mTransformation;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[i]];
    const int base = static_cast<int>(out.triangles.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D p = transform * mesh->mVertices[v];
      out.triangles.vertices.emplace_back(p.x, p.y, p.z);
      sum += out.triangles.vertices.back();
      ++count;
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3) {
        const unsigned* idx = mesh->mFaces[f].mIndices;
        out.triangles.faces.push_back({base + static_cast<int>(idx[0]), base + static_cast<int>(idx[1]),
                                       base + static_cast<int>(idx[2])});
      }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collect(scene, node->mChildren[c], transform, out, sum, count);
}

}  // namespace

std::optional<OmplAppImport> importAsOmplApp(const std::string& path, bool upAxis) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, !upAxis);
  const aiScene* scene = importer.ReadFile(path, aiProcess_GenNormals | aiProcess_Triangulate |
                                                     aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                                     aiProcess_OptimizeGraph);
  if (!scene || !scene->mRootNode || !scene->HasMeshes()) return std::nullopt;
  OmplAppImport out;
  acd::Vec3 sum = acd::Vec3::Zero();
  long count = 0;
  collect(scene, scene->mRootNode, aiMatrix4x4(), out, sum, count);
  if (count == 0 || out.triangles.faces.empty()) return std::nullopt;
  out.center = sum / static_cast<double>(count);
  return out;
}

}  // namespace planner
