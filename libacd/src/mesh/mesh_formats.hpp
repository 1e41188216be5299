// The mesh file formats, each a reader over the whole file in memory and a writer to bytes:
// io_off.cpp, io_obj.cpp, io_ply.cpp, io_stl.cpp. io.cpp picks one by file extension.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace acd::format {

Status readOff(std::string_view text, const std::string& path, TriMesh& mesh);
std::string offText(const TriMesh& mesh);

struct ObjGroup {
  std::string name;
  size_t firstFace = 0;
};

struct ObjFile {
  TriMesh mesh;
  std::vector<ObjGroup> groups;  // in file order; faces before any `o`/`g` form an unnamed group
};

Status readObj(std::string_view text, const std::string& path, ObjFile& obj);
/// The `v` and `f` lines of one mesh whose first vertex has the file's index firstVertex.
void appendObjBody(std::string& out, const TriMesh& mesh, long long firstVertex);

Status readPly(std::string_view text, const std::string& path, TriMesh& mesh);
std::string plyBytes(const TriMesh& mesh);

/// Binary or ASCII, told apart by content.
Status readStl(std::string_view data, const std::string& path, TriMesh& mesh);
std::string stlBytes(const TriMesh& mesh);

}  // namespace acd::format
