// STL files, binary and ASCII; corners at the same position become one vertex.
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

/// Merges STL corners with exactly the same position (+0 and -0 are the same position).
class PositionIndex {
 public:
  int indexOf(const Vec3& p, std::vector<Vec3>& vertices) {
    const Key key{bits(p.x()), bits(p.y()), bits(p.z())};
    const auto [it, inserted] = index_.emplace(key, static_cast<int>(vertices.size()));
    if (inserted) vertices.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h ^= (k[1] + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2));
      h ^= (k[2] + 0x94D049BB133111EBull + (h << 6) + (h >> 2));
      return static_cast<size_t>(h);
    }
  };
  static std::uint64_t bits(double x) {
    x += 0.0;  // turns -0 into +0
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  std::unordered_map<Key, int, KeyHash> index_;
};

constexpr size_t kStlHeaderBytes = 84;  // 80-byte header + uint32 triangle count
constexpr size_t kStlTriangleBytes = 50;

float loadLittleFloat(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  const std::uint32_t u = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

std::uint32_t loadLittleUint32(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

Status readBinaryStl(std::string_view data, const std::string& path, TriMesh& mesh) {
  if (data.size() < kStlHeaderBytes)
    return Status::error(StatusCode::FileUnreadable,
                         path + ": not an STL: " + std::to_string(data.size()) +
                             " bytes is too short for binary STL, and it does not start with 'solid'");
  const std::uint32_t triangles = loadLittleUint32(data.data() + 80);
  const unsigned long long expected = kStlHeaderBytes + 50ull * triangles;
  if (data.size() != expected)
    return Status::error(StatusCode::FileUnreadable,
                         path + ": truncated or corrupt binary STL: the header announces " + std::to_string(triangles) +
                             " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                             std::to_string(data.size()) + " bytes");
  PositionIndex positions;
  mesh.faces.reserve(triangles);
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const char* corner = data.data() + kStlHeaderBytes + kStlTriangleBytes * t + 12;  // skip the normal
    Face face;
    for (int k = 0; k < 3; ++k, corner += 12)
      face[k] = positions.indexOf(Vec3(loadLittleFloat(corner), loadLittleFloat(corner + 4),
                                       loadLittleFloat(corner + 8)), mesh.vertices);
    mesh.faces.push_back(face);
  }
  return Status::success();
}

Status readAsciiStl(std::string_view text, const std::string& path, TriMesh& mesh) {
  LineReader lines(text, /*stripComments=*/false);
  std::string_view line, token;
  auto fail = [&](const std::string& msg) {
    return Status::error(StatusCode::FileUnreadable, path + ": line " + std::to_string(lines.number()) + ": " + msg);
  };
  PositionIndex positions;
  std::vector<int> polygon;
  bool inLoop = false;
  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(token)) continue;
    if (token == "vertex") {
      if (!inLoop) return fail("'vertex' outside 'outer loop'");
      double xyz[3];
      for (double& c : xyz) {
        if (!tokens.next(token)) return fail("expected 3 coordinates");
        if (!parseDouble(token, c)) return fail(quoted(token) + " is not a number");
      }
      polygon.push_back(positions.indexOf(Vec3(xyz[0], xyz[1], xyz[2]), mesh.vertices));
    } else if (token == "outer") {
      inLoop = true;
      polygon.clear();
    } else if (token == "endloop") {
      if (polygon.size() < 3)
        return fail("facet has " + std::to_string(polygon.size()) + " vertices; need at least 3");
      fanTriangulate(polygon, mesh.faces);
      inLoop = false;
    } else if (token != "solid" && token != "endsolid" && token != "facet" && token != "endfacet") {
      return fail("unexpected " + quoted(token));
    }
  }
  if (inLoop) return fail("unexpected end of file inside a facet");
  return Status::success();
}

bool looksLikeAsciiStl(std::string_view data) {
  const size_t start = data.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || data.substr(start, 5) != "solid") return false;
  // Binary files may start with "solid" too, but their float data and attribute words contain zero bytes.
  return std::memchr(data.data(), '\0', data.size()) == nullptr;
}

}  // namespace

Status readStl(std::string_view data, const std::string& path, TriMesh& mesh) {
  if (looksLikeAsciiStl(data)) return readAsciiStl(data, path, mesh);
  return readBinaryStl(data, path, mesh);
}

std::string stlBytes(const TriMesh& mesh) {
  // The header must not start with "solid": readers would take the file for ASCII.
  std::string out = "binary STL written by acd";
  out.resize(80, ' ');
  out.reserve(kStlHeaderBytes + kStlTriangleBytes * mesh.faces.size());
  appendLittleEndian(out, static_cast<std::uint32_t>(mesh.faces.size()));
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    Vec3 normal = faceNormal(mesh, f);
    const double length = normal.norm();
    normal = length > 0.0 ? Vec3(normal / length) : Vec3::Zero();
    for (int c = 0; c < 3; ++c) appendLittleEndian(out, static_cast<float>(normal[c]));
    for (int v : mesh.faces[f])
      for (int c = 0; c < 3; ++c) appendLittleEndian(out, static_cast<float>(mesh.vertices[v][c]));
    appendLittleEndian<std::uint16_t>(out, 0);
  }
  return out;
}

}  // namespace acd::format
