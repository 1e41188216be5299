// Scene files read through assimp: glTF 2 (.gltf, .glb), COLLADA (.dae), 3MF (.3mf), FBX (.fbx).
// A scene is a tree of nodes, each with a transform, that place meshes; the same mesh may be
// placed several times. readMesh (acd/io.hpp) merges a scene into one mesh; readScene keeps
// every placed mesh apart (`acd decompose --per-mesh`).
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace acd {

/// True for the extensions (case-insensitive) read through assimp.
bool isSceneFormat(const std::string& path);

struct SceneMeshes {
  Status status;
  std::vector<TriMesh> meshes;     // one per placement of a mesh in the node tree, depth first
  std::vector<std::string> names;  // "node/mesh", or "node" when the mesh has no name; never empty
};

/// Reads every mesh placed in the scene with its node's full transform (the product of the
/// transforms from the root) applied, in the file's own coordinates and units (no turning of
/// COLLADA's Z-up into Y-up). Polygons are triangulated; points and lines are dropped; a
/// mirroring transform reverses the faces so that they keep facing outward. Vertices are as
/// assimp gives them (corners split by normals or texture coordinates are merged later, by
/// position, in prepareSolid). Never throws: an unreadable file, or one with no triangles,
/// comes back as a Status naming the file.
SceneMeshes readScene(const std::string& path);

/// The same from bytes in memory; `name` gives the format by its extension and names the
/// scene in messages. A glTF that refers to files beside it cannot be read this way.
SceneMeshes readSceneFromMemory(std::string_view data, const std::string& name);

}  // namespace acd
