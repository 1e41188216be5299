// Wavefront OBJ files: vertices and faces, with `o` and `g` lines naming groups of faces.
#include "mesh_formats.hpp"

#include "format_text.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace acd::format {

namespace {

bool looksLikeKeyword(std::string_view token) {
  if (token.empty() || !std::isalpha(static_cast<unsigned char>(token[0]))) return false;
  return std::all_of(token.begin(), token.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

}  // namespace

Status readObj(std::string_view text, const std::string& path, ObjFile& obj) {
  LineReader lines(text);
  std::string_view line, token;
  auto fail = [&](StatusCode code, const std::string& msg) {
    return Status::error(code, path + ": line " + std::to_string(lines.number()) + ": " + msg);
  };
  TriMesh& mesh = obj.mesh;
  // OBJ allows indices to vertices defined later; check those once all vertices are known.
  struct ForwardReference {
    int line;
    long long face, index;
  };
  std::vector<ForwardReference> forward;
  std::vector<int> polygon;
  long long polygonCount = 0;

  auto startGroup = [&](std::string name) {
    // `o name` directly followed by `g other` names one object, not an empty one and another.
    if (!obj.groups.empty() && obj.groups.back().firstFace == mesh.faces.size())
      obj.groups.back().name = std::move(name);
    else
      obj.groups.push_back({std::move(name), mesh.faces.size()});
  };

  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(token)) continue;
    if (token == "v") {
      double xyz[3];
      for (double& c : xyz) {
        std::string_view number;
        if (!tokens.next(number)) return fail(StatusCode::FileUnreadable, "expected 3 coordinates");
        if (!parseDouble(number, c)) return fail(StatusCode::FileUnreadable, quoted(number) + " is not a number");
      }
      mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (token == "f") {
      polygon.clear();
      std::string_view corner;
      while (tokens.next(corner)) {
        // "a", "a/b", "a//c", "a/b/c": only the position index matters.
        const std::string_view position = corner.substr(0, corner.find('/'));
        long long index = 0;
        if (!parseInteger(position, index))
          return fail(StatusCode::FileUnreadable, quoted(corner) + " is not a vertex index");
        const long long defined = static_cast<long long>(mesh.vertices.size());
        if (index == 0) return fail(StatusCode::IndexOutOfRange, "vertex index 0 (OBJ indices start at 1)");
        if (index < 0) {
          index += defined;  // relative to the vertices defined so far
          if (index < 0)
            return fail(StatusCode::IndexOutOfRange,
                        "face " + std::to_string(polygonCount) + " refers to vertex " + std::string(position) +
                            " but only " + std::to_string(defined) + " vertices are defined before it");
        } else {
          --index;
          if (index >= defined) forward.push_back({lines.number(), polygonCount, index});
        }
        if (index > std::numeric_limits<int>::max())
          return fail(StatusCode::IndexOutOfRange, "vertex index " + std::string(position) + " is too large");
        polygon.push_back(static_cast<int>(index));
      }
      if (polygon.size() < 3)
        return fail(StatusCode::FileUnreadable, "face " + std::to_string(polygonCount) + " has " +
                                                    std::to_string(polygon.size()) + " vertices; need at least 3");
      if (obj.groups.empty()) obj.groups.push_back({"", mesh.faces.size()});
      fanTriangulate(polygon, mesh.faces);
      ++polygonCount;
    } else if (token == "o" || token == "g") {
      startGroup(std::string(tokens.rest()));
    } else if (!looksLikeKeyword(token)) {
      // vt, vn, usemtl, s, l, ... are skipped; what is not even a keyword means this is not an OBJ.
      return fail(StatusCode::FileUnreadable, "unexpected " + quoted(token));
    }
  }
  for (const ForwardReference& ref : forward)
    if (ref.index >= static_cast<long long>(mesh.vertices.size()))
      return Status::error(StatusCode::IndexOutOfRange, path + ": line " + std::to_string(ref.line) + ": " +
                                                            outOfRange(ref.face, ref.index + 1, mesh.vertices.size()) +
                                                            " (OBJ indices start at 1)");
  return Status::success();
}

void appendObjBody(std::string& out, const TriMesh& mesh, long long firstVertex) {
  for (const Vec3& p : mesh.vertices) appendVertexLine(out, "v ", p);
  for (const Face& f : mesh.faces) {
    out += 'f';
    for (int v : f) {
      out += ' ';
      appendInteger(out, firstVertex + v + 1);
    }
    out += '\n';
  }
}

}  // namespace acd::format
