// Mesh files. Hand-written parsers over the whole file in memory: input meshes
// can have millions of faces, and bad input must come back as a Status naming
// the line or element, never as an exception.
#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#include "mesh_formats.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string_view>
#include <unordered_map>

namespace acd {
namespace {

// ---------------------------------------------------------------- formats

enum class Format { Off, Obj, Ply, Stl, Unknown };

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Format formatOf(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".off") return Format::Off;
  if (ext == ".obj") return Format::Obj;
  if (ext == ".ply") return Format::Ply;
  if (ext == ".stl") return Format::Stl;
  return Format::Unknown;
}

Status unsupportedFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  const std::string what = ext.empty() ? "no file extension" : "unsupported extension '" + ext + "'";
  return Status::error(StatusCode::UnsupportedFormat, path + ": " + what + " (expected .off, .obj, .ply, .stl, .gltf, .glb, .dae, .3mf or .fbx)");
}

// ---------------------------------------------------------------- whole files

Status readWholeFile(const std::string& path, std::string& data) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return Status::error(StatusCode::FileUnreadable, path + ": is a directory");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return Status::error(StatusCode::FileUnreadable, path + ": cannot open: " + std::strerror(errno));
  // Read in chunks rather than trusting a size: works for pipes and files that change under us.
  // The size, when known, only reserves the string (no copy on every growth of a large file).
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size < (std::uintmax_t(1) << 34)) data.reserve(size);
  char chunk[1 << 16];
  size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) data.append(chunk, got);
  const bool failed = std::ferror(file) != 0;
  const int err = errno;
  std::fclose(file);
  if (failed) return Status::error(StatusCode::FileUnreadable, path + ": read error: " + std::strerror(err));
  return Status::success();
}

Status writeWholeFile(const std::string& path, const std::string& data) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return Status::error(StatusCode::FileUnreadable, path + ": cannot create: " + std::strerror(errno));
  const bool written = std::fwrite(data.data(), 1, data.size(), file) == data.size();
  const int err = errno;
  // fclose flushes: a full disk may only show up here.
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed)
    return Status::error(StatusCode::FileUnreadable, path + ": write error: " + std::strerror(written ? errno : err));
  return Status::success();
}

/// Runs a reader, turning an allocation failure on a hostile file into a Status.
template <class Read>
Status guarded(const std::string& path, Read&& read) {
  try {
    return read();
  } catch (const std::exception& e) {
    return Status::error(StatusCode::FileUnreadable, path + ": " + e.what());
  }
}

}  // namespace

ReadResult readMeshFromMemory(std::string_view data, const std::string& name) {
  ReadResult result;
  if (isSceneFormat(name)) {  // through assimp: every placed mesh, merged into one
    SceneMeshes scene = readSceneFromMemory(data, name);
    result.status = scene.status;
    if (scene.status.ok()) result.mesh = concatenate(scene.meshes);
    return result;
  }
  const Format format = formatOf(name);
  if (format == Format::Unknown) {
    result.status = unsupportedFormat(name);
    return result;
  }
  result.status = guarded(name, [&]() -> Status {
    if (data.empty()) return Status::error(StatusCode::EmptyMesh, name + ": file is empty");
    Status s;
    switch (format) {
      case Format::Off: s = format::readOff(data, name, result.mesh); break;
      case Format::Obj: {
        format::ObjFile obj;
        s = format::readObj(data, name, obj);
        result.mesh = std::move(obj.mesh);
        break;
      }
      case Format::Ply: s = format::readPly(data, name, result.mesh); break;
      case Format::Stl: s = format::readStl(data, name, result.mesh); break;
      case Format::Unknown: break;
    }
    if (s.ok() && result.mesh.faces.empty())
      s = Status::error(StatusCode::EmptyMesh,
                        name + ": no faces (" + std::to_string(result.mesh.vertices.size()) + " vertices)");
    return s;
  });
  if (!result.status.ok()) result.mesh = TriMesh{};
  return result;
}

ReadResult readMesh(const std::string& path) {
  if (isSceneFormat(path)) {  // from the file: a .gltf may refer to buffers and images beside it
    SceneMeshes scene = readScene(path);
    if (!scene.status.ok()) return {scene.status, {}};
    return {scene.status, concatenate(scene.meshes)};
  }
  if (formatOf(path) == Format::Unknown) return {unsupportedFormat(path), {}};
  std::string data;
  const Status read = guarded(path, [&] { return readWholeFile(path, data); });
  if (!read.ok()) return {read, {}};
  return readMeshFromMemory(data, path);
}

Status writeMesh(const std::string& path, const TriMesh& mesh) {
  return guarded(path, [&]() -> Status {
    switch (formatOf(path)) {
      case Format::Off: return writeWholeFile(path, format::offText(mesh));
      case Format::Obj: {
        std::string out;
        format::appendObjBody(out, mesh, 0);
        return writeWholeFile(path, out);
      }
      case Format::Ply: return writeWholeFile(path, format::plyBytes(mesh));
      case Format::Stl: return writeWholeFile(path, format::stlBytes(mesh));
      case Format::Unknown: break;
    }
    return unsupportedFormat(path);
  });
}

std::string objObjectsText(const std::vector<TriMesh>& meshes, const std::vector<std::string>& names) {
  std::string out;
  long long firstVertex = 0;
  for (size_t i = 0; i < meshes.size() && i < names.size(); ++i) {
    // A name is the rest of its line: no line breaks, and never empty.
    std::string name = names[i];
    std::replace(name.begin(), name.end(), '\n', ' ');
    std::replace(name.begin(), name.end(), '\r', ' ');
    if (name.find_first_not_of(" \t") == std::string::npos) name = "object_" + std::to_string(i);
    out += "o " + name + "\n";
    format::appendObjBody(out, meshes[i], firstVertex);
    firstVertex += static_cast<long long>(meshes[i].vertices.size());
  }
  return out;
}

Status writeObjObjects(const std::string& path, const std::vector<TriMesh>& meshes,
                       const std::vector<std::string>& names) {
  if (meshes.size() != names.size())
    return Status::error(StatusCode::InvalidParameter, path + ": " + std::to_string(meshes.size()) + " meshes but " +
                                                           std::to_string(names.size()) + " names");
  return guarded(path, [&]() -> Status { return writeWholeFile(path, objObjectsText(meshes, names)); });
}

ObjObjects readObjObjects(const std::string& path) {
  if (formatOf(path) != Format::Obj) return readObjObjectsFromMemory({}, path);
  std::string data;
  const Status read = guarded(path, [&] { return readWholeFile(path, data); });
  if (!read.ok()) return {read, {}, {}};
  return readObjObjectsFromMemory(data, path);
}

ObjObjects readObjObjectsFromMemory(std::string_view data, const std::string& path) {
  ObjObjects result;
  if (formatOf(path) != Format::Obj) {
    result.status = formatOf(path) == Format::Unknown
                        ? unsupportedFormat(path)
                        : Status::error(StatusCode::UnsupportedFormat, path + ": objects can only be read from OBJ");
    return result;
  }
  result.status = guarded(path, [&]() -> Status {
    if (data.empty()) return Status::error(StatusCode::EmptyMesh, path + ": file is empty");
    format::ObjFile obj;
    if (Status s = format::readObj(data, path, obj); !s.ok()) return s;
    // OBJ indices are global: renumber each object's vertices, keeping the file's order.
    // Not compact() on a full copy: a file with hundreds of hulls would copy every vertex per hull.
    std::vector<int> localIndex(obj.mesh.vertices.size(), -1);
    std::vector<int> used;
    for (size_t g = 0; g < obj.groups.size(); ++g) {
      const size_t begin = obj.groups[g].firstFace;
      const size_t end = g + 1 < obj.groups.size() ? obj.groups[g + 1].firstFace : obj.mesh.faces.size();
      if (begin == end) continue;  // a trailing `o` with no faces
      used.clear();
      for (size_t f = begin; f < end; ++f)
        for (int v : obj.mesh.faces[f])
          if (localIndex[v] < 0) {
            localIndex[v] = 0;
            used.push_back(v);
          }
      std::sort(used.begin(), used.end());
      TriMesh piece;
      piece.vertices.reserve(used.size());
      for (int v : used) {
        localIndex[v] = static_cast<int>(piece.vertices.size());
        piece.vertices.push_back(obj.mesh.vertices[v]);
      }
      piece.faces.reserve(end - begin);
      for (size_t f = begin; f < end; ++f) {
        const Face& face = obj.mesh.faces[f];
        piece.faces.push_back({localIndex[face[0]], localIndex[face[1]], localIndex[face[2]]});
      }
      for (int v : used) localIndex[v] = -1;
      result.objects.push_back(std::move(piece));
      result.names.push_back(obj.groups[g].name);
    }
    if (result.objects.empty())
      return Status::error(StatusCode::EmptyMesh,
                           path + ": no faces (" + std::to_string(obj.mesh.vertices.size()) + " vertices)");
    return Status::success();
  });
  if (!result.status.ok()) {
    result.objects.clear();
    result.names.clear();
  }
  return result;
}

}  // namespace acd
