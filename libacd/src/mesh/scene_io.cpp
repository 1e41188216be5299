// Scene formats through assimp. The node tree is walked here rather than flattened by assimp's
// PreTransformVertices, so that each placement of a mesh stays a mesh of its own (--per-mesh)
// and the transforms are composed in double precision.
#include <acd/scene_io.hpp>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Core>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>

namespace acd {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

TriMesh placedMesh(const aiMesh& mesh, const Eigen::Matrix4d& transform) {
  TriMesh out;
  out.vertices.reserve(mesh.mNumVertices);
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    const Eigen::Vector4d q = transform * Eigen::Vector4d(p.x, p.y, p.z, 1.0);
    // Projective transforms do not occur in these formats; divide anyway rather than drop w.
    out.vertices.emplace_back(q.x() / q.w(), q.y() / q.w(), q.z() / q.w());
  }
  const bool mirrored = transform.topLeftCorner<3, 3>().determinant() < 0.0;
  const unsigned n = mesh.mNumVertices;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines
    const unsigned a = face.mIndices[0], b = face.mIndices[1], c = face.mIndices[2];
    if (a >= n || b >= n || c >= n) continue;  // assimp validates, but a bad index must never reach us
    Face t{static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)};
    if (mirrored) std::swap(t[1], t[2]);
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace

bool isSceneFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".gltf" || ext == ".glb" || ext == ".dae" || ext == ".3mf" || ext == ".fbx";
}

namespace {

/// Reads with `read(importer, flags)` and collects every placed mesh; messages start with `name`.
template <class Read>
SceneMeshes collect(const std::string& name, Read&& read) {
  SceneMeshes out;
  auto failed = [&](StatusCode code, const std::string& message) {
    out.meshes.clear();
    out.names.clear();
    out.status = Status::error(code, name + ": " + message);
    return out;
  };
  if (!isSceneFormat(name))
    return failed(StatusCode::UnsupportedFormat, "not a scene format (expected .gltf, .glb, .dae, .3mf or .fbx)");
  try {
    Assimp::Importer importer;
    // Coordinates as written in the file, as for the other formats (and as the planner reads them).
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    // Only geometry matters: no points or lines.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene =
        read(importer, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_JoinIdenticalVertices);
    if (!scene) return failed(StatusCode::FileUnreadable, std::string("cannot read: ") + importer.GetErrorString());
    if (!scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
      return failed(StatusCode::FileUnreadable, "cannot read: the scene is incomplete");
    // Depth first, children in file order; a node that is its own ancestor cannot come from
    // assimp, but the depth cap keeps a corrupt tree from recursing without end.
    std::function<void(const aiNode&, const Eigen::Matrix4d&, const std::string&, int)> visit =
        [&](const aiNode& node, const Eigen::Matrix4d& parent, const std::string& prefix, int depth) {
          if (depth > 256) return;
          const Eigen::Matrix4d transform = parent * toEigen(node.mTransformation);
          const std::string nodeName = node.mName.length > 0 ? std::string(node.mName.C_Str()) : "node";
          const std::string full = prefix.empty() ? nodeName : prefix + "/" + nodeName;
          for (unsigned k = 0; k < node.mNumMeshes; ++k) {
            const unsigned m = node.mMeshes[k];
            if (m >= scene->mNumMeshes || !scene->mMeshes[m]) continue;
            const aiMesh& mesh = *scene->mMeshes[m];
            TriMesh placed = placedMesh(mesh, transform);
            if (placed.faces.empty()) continue;
            out.meshes.push_back(std::move(placed));
            out.names.push_back(mesh.mName.length > 0 ? full + "/" + mesh.mName.C_Str() : full);
          }
          for (unsigned c = 0; c < node.mNumChildren; ++c)
            if (node.mChildren[c]) visit(*node.mChildren[c], transform, depth == 0 ? std::string() : full, depth + 1);
        };
    visit(*scene->mRootNode, Eigen::Matrix4d::Identity(), std::string(), 0);
  } catch (const std::exception& e) {
    return failed(StatusCode::FileUnreadable, std::string("cannot read: ") + e.what());
  }
  if (out.meshes.empty()) return failed(StatusCode::EmptyMesh, "no triangles in the scene");
  out.status = Status::success();
  return out;
}

}  // namespace

SceneMeshes readScene(const std::string& path) {
  std::error_code ec;
  if (isSceneFormat(path) && !std::filesystem::is_regular_file(path, ec)) {
    SceneMeshes out;
    out.status = Status::error(StatusCode::FileUnreadable,
                               path + (std::filesystem::exists(path, ec) ? ": not a regular file" : ": cannot open: no such file"));
    return out;
  }
  return collect(path, [&](Assimp::Importer& importer, unsigned flags) { return importer.ReadFile(path, flags); });
}

SceneMeshes readSceneFromMemory(std::string_view data, const std::string& name) {
  const std::string hint = lowerExtension(name).substr(std::min<std::size_t>(1, lowerExtension(name).size()));
  return collect(name, [&](Assimp::Importer& importer, unsigned flags) -> const aiScene* {
    if (data.empty()) return nullptr;
    return importer.ReadFileFromMemory(data.data(), data.size(), flags, hint.c_str());
  });
}

}  // namespace acd
