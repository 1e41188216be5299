// OFF files: "OFF", the counts, vertex lines, polygon lines (fan-triangulated).
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

Status readOff(std::string_view text, const std::string& path, TriMesh& mesh) {
  LineReader lines(text);
  Tokens tokens;
  auto fail = [&](StatusCode code, const std::string& msg) {
    return Status::error(code, path + ": line " + std::to_string(lines.number()) + ": " + msg);
  };
  std::string_view token;
  if (!nextContentLine(lines, tokens) || !tokens.next(token))
    return Status::error(StatusCode::FileUnreadable, path + ": no OFF header");
  // Prefixes ST (texture), C (colour), N (normals) only add values after x y z, which we ignore.
  const bool offHeader = token.size() >= 3 && token.substr(token.size() - 3) == "OFF" &&
                         token.substr(0, token.size() - 3).find_first_not_of("STCN") == std::string_view::npos;
  if (!offHeader) {
    if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF")
      return fail(StatusCode::FileUnreadable, "unsupported OFF variant " + quoted(token) + " (only 3D OFF is read)");
    return fail(StatusCode::FileUnreadable, "expected OFF header, found " + quoted(token));
  }
  std::string_view extra;
  if (Tokens probe = tokens; probe.next(extra) && extra == "BINARY")
    return fail(StatusCode::FileUnreadable, "binary OFF is not supported");

  // The counts may follow the keyword on the same line.
  if (!tokens.next(token)) {
    if (!nextContentLine(lines, tokens) || !tokens.next(token))
      return fail(StatusCode::FileUnreadable, "unexpected end of file: expected vertex and face counts");
  }
  long long vertexCount = 0, faceCount = 0;
  std::string_view faceToken;
  if (!parseInteger(token, vertexCount) || !tokens.next(faceToken) || !parseInteger(faceToken, faceCount) ||
      vertexCount < 0 || faceCount < 0)
    return fail(StatusCode::FileUnreadable, "expected vertex and face counts");

  reserveAtMost(mesh.vertices, vertexCount, text.size(), 6);
  for (long long v = 0; v < vertexCount; ++v) {
    if (!nextContentLine(lines, tokens))
      return fail(StatusCode::FileUnreadable, "unexpected end of file: read " + std::to_string(v) + " of " +
                                                  std::to_string(vertexCount) + " vertices");
    double xyz[3];
    for (double& c : xyz) {
      if (!tokens.next(token)) return fail(StatusCode::FileUnreadable, "expected 3 coordinates");
      if (!parseDouble(token, c)) return fail(StatusCode::FileUnreadable, quoted(token) + " is not a number");
    }
    mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  reserveAtMost(mesh.faces, faceCount, text.size(), 8);
  std::vector<int> polygon;
  for (long long f = 0; f < faceCount; ++f) {
    if (!nextContentLine(lines, tokens))
      return fail(StatusCode::FileUnreadable,
                  "unexpected end of file: read " + std::to_string(f) + " of " + std::to_string(faceCount) + " faces");
    long long corners = 0;
    if (!tokens.next(token) || !parseInteger(token, corners))
      return fail(StatusCode::FileUnreadable, "expected a vertex count, found " + quoted(token));
    if (corners < 3)
      return fail(StatusCode::FileUnreadable,
                  "face " + std::to_string(f) + " has " + std::to_string(corners) + " vertices; need at least 3");
    polygon.clear();
    for (long long k = 0; k < corners; ++k) {
      long long index = 0;
      if (!tokens.next(token))
        return fail(StatusCode::FileUnreadable, "expected " + std::to_string(corners) + " vertex indices");
      if (!parseInteger(token, index))
        return fail(StatusCode::FileUnreadable, quoted(token) + " is not a vertex index");
      if (index < 0 || index >= vertexCount)
        return fail(StatusCode::IndexOutOfRange, outOfRange(f, index, mesh.vertices.size()));
      polygon.push_back(static_cast<int>(index));
    }
    fanTriangulate(polygon, mesh.faces);  // anything after the indices is a colour
  }
  return Status::success();
}

std::string offText(const TriMesh& mesh) {
  std::string out = "OFF\n";
  appendInteger(out, static_cast<long long>(mesh.vertices.size()));
  out += ' ';
  appendInteger(out, static_cast<long long>(mesh.faces.size()));
  out += " 0\n";
  for (const Vec3& p : mesh.vertices) appendVertexLine(out, "", p);
  for (const Face& f : mesh.faces) {
    out += '3';
    for (int v : f) {
      out += ' ';
      appendInteger(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace acd::format
