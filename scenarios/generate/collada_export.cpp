#include "collada_export.hpp"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <cstdio>
#include <filesystem>
#include <memory>

namespace scenes {

namespace {

/// An aiScene owns its arrays (deleted with delete[] by its destructor): built with new[].
std::unique_ptr<aiScene> sceneOf(const Soup& soup) {
  auto scene = std::make_unique<aiScene>();
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
  const unsigned n = static_cast<unsigned>(soup.pieces.size());
  scene->mNumMeshes = n;
  scene->mMeshes = new aiMesh*[n];
  scene->mRootNode = new aiNode("root");
  scene->mRootNode->mNumChildren = n;
  scene->mRootNode->mChildren = new aiNode*[n];
  for (unsigned i = 0; i < n; ++i) {
    const acd::TriMesh& piece = soup.pieces[i];
    auto* mesh = new aiMesh();
    mesh->mName = soup.names[i];
    mesh->mMaterialIndex = 0;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = static_cast<unsigned>(piece.vertices.size());
    mesh->mVertices = new aiVector3D[mesh->mNumVertices];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const acd::Vec3& p = piece.vertices[v];
      mesh->mVertices[v] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
    }
    mesh->mNumFaces = static_cast<unsigned>(piece.faces.size());
    mesh->mFaces = new aiFace[mesh->mNumFaces];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      aiFace& face = mesh->mFaces[f];
      face.mNumIndices = 3;
      face.mIndices = new unsigned[3];
      for (int k = 0; k < 3; ++k) face.mIndices[k] = static_cast<unsigned>(piece.faces[f][k]);
    }
    scene->mMeshes[i] = mesh;
    auto* node = new aiNode(soup.names[i]);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{i};
    scene->mRootNode->mChildren[i] = node;
  }
  return scene;
}

}  // namespace

std::string writeCollada(const std::string& path, const Soup& soup) {
  if (soup.pieces.empty()) return path + ": nothing to write";
  const std::unique_ptr<aiScene> scene = sceneOf(soup);
  const std::string partial = path + ".partial";
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), "collada", partial) != aiReturn_SUCCESS)
    return path + ": " + exporter.GetErrorString();
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) return path + ": " + ec.message();
  return {};
}

}  // namespace scenes
