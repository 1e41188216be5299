// Mesh files: OFF, OBJ, PLY (ASCII and binary), STL (ASCII and binary); scene formats
// (glTF, COLLADA, 3MF, FBX) through assimp, see acd/scene_io.hpp.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace acd {

struct ReadResult {
  Status status;
  TriMesh mesh;  // polygons are fan-triangulated; STL corners are merged by exact position
};

/// Reads a mesh by file extension (case-insensitive); a scene file gives all its placed meshes,
/// transforms applied, merged into one (acd::readScene keeps them apart). Never throws: a missing
/// file, a parse error or an unknown extension comes back as a Status naming it.
ReadResult readMesh(const std::string& path);

/// Reads a mesh from bytes in memory, exactly as readMesh reads a file: `name`'s extension
/// picks the format and `name` starts every error message.
ReadResult readMeshFromMemory(std::string_view data, const std::string& name);

/// Writes by extension (.off, .obj, .ply, .stl).
Status writeMesh(const std::string& path, const TriMesh& mesh);

/// One OBJ with one `o NAME` object per mesh: the form physics engines load.
Status writeObjObjects(const std::string& path, const std::vector<TriMesh>& meshes,
                       const std::vector<std::string>& names);

/// The text writeObjObjects writes (meshes.size() must equal names.size()).
std::string objObjectsText(const std::vector<TriMesh>& meshes, const std::vector<std::string>& names);

struct ObjObjects {
  Status status;
  std::vector<TriMesh> objects;  // one per `o` or `g` group, vertices compacted
  std::vector<std::string> names;
};

/// Reads an OBJ that holds several objects (ours, CoACD's or V-HACD's hull files).
ObjObjects readObjObjects(const std::string& path);
ObjObjects readObjObjectsFromMemory(std::string_view data, const std::string& name);

}  // namespace acd
