// PLY files: ASCII and binary of either byte order.
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

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool plyTypeFromName(std::string_view name, PlyType& type) {
  static const std::pair<const char*, PlyType> kNames[] = {
      {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [n, t] : kNames)
    if (name == n) {
      type = t;
      return true;
    }
  return false;
}

size_t plyTypeSize(PlyType type) {
  switch (type) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 1;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // item type for lists
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  size_t bodyOffset = 0;
};

Status readPlyHeader(std::string_view text, const std::string& path, PlyHeader& header) {
  LineReader lines(text, /*stripComments=*/false);
  std::string_view line, token;
  auto fail = [&](const std::string& msg) {
    return Status::error(StatusCode::FileUnreadable, path + ": line " + std::to_string(lines.number()) + ": " + msg);
  };
  if (!lines.next(line) || !Tokens(line).next(token) || token != "ply")
    return Status::error(StatusCode::FileUnreadable, path + ": line 1: expected 'ply' header");
  bool sawFormat = false;
  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(token)) continue;
    if (token == "comment" || token == "obj_info") continue;
    if (token == "end_header") {
      if (!sawFormat) return fail("no 'format' line in the header");
      header.bodyOffset = lines.offset();
      return Status::success();
    }
    if (token == "format") {
      std::string_view encoding;
      tokens.next(encoding);
      if (encoding == "ascii") header.encoding = PlyEncoding::Ascii;
      else if (encoding == "binary_little_endian") header.encoding = PlyEncoding::BinaryLittleEndian;
      else if (encoding == "binary_big_endian") header.encoding = PlyEncoding::BinaryBigEndian;
      else return fail("unknown PLY format " + quoted(encoding));
      sawFormat = true;
    } else if (token == "element") {
      PlyElement element;
      std::string_view name, count;
      if (!tokens.next(name) || !tokens.next(count) || !parseInteger(count, element.count) || element.count < 0)
        return fail("expected 'element NAME COUNT'");
      element.name = std::string(name);
      header.elements.push_back(std::move(element));
    } else if (token == "property") {
      if (header.elements.empty()) return fail("property before any element");
      PlyProperty property;
      std::string_view type, name;
      if (!tokens.next(type)) return fail("expected a property type");
      if (type == "list") {
        std::string_view countType;
        property.isList = true;
        if (!tokens.next(countType) || !plyTypeFromName(countType, property.countType))
          return fail("unknown list count type " + quoted(countType));
        if (!tokens.next(type)) return fail("expected a list item type");
      }
      if (!plyTypeFromName(type, property.type)) return fail("unknown property type " + quoted(type));
      if (!tokens.next(name)) return fail("expected a property name");
      property.name = std::string(name);
      header.elements.back().properties.push_back(std::move(property));
    } else {
      return fail("unexpected " + quoted(token) + " in the header");
    }
  }
  return Status::error(StatusCode::FileUnreadable, path + ": no 'end_header' line");
}

/// PLY body values as text: whitespace-separated, element boundaries not tied to lines.
class PlyAsciiValues {
 public:
  explicit PlyAsciiValues(std::string_view body, int firstLine) : lines_(body, false), firstLine_(firstLine) {}

  bool read(PlyType, double& value, std::string& error) {
    std::string_view token;
    while (!tokens_.next(token)) {
      std::string_view line;
      if (!lines_.next(line)) {
        error = "unexpected end of file";
        return false;
      }
      tokens_ = Tokens(line);
    }
    if (!parseDouble(token, value)) {
      error = "line " + std::to_string(firstLine_ + lines_.number()) + ": " + quoted(token) + " is not a number";
      return false;
    }
    return true;
  }

 private:
  LineReader lines_;
  Tokens tokens_;
  int firstLine_;
};

/// PLY body values in binary, converted from the file's byte order.
class PlyBinaryValues {
 public:
  PlyBinaryValues(std::string_view body, bool bigEndian) : body_(body) {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    swap_ = (first == 1) == bigEndian;
  }

  bool read(PlyType type, double& value, std::string& error) {
    const size_t size = plyTypeSize(type);
    if (body_.size() - pos_ < size) {
      error = "unexpected end of file (truncated binary data)";
      return false;
    }
    unsigned char b[8];
    std::memcpy(b, body_.data() + pos_, size);
    pos_ += size;
    if (swap_) std::reverse(b, b + size);
    switch (type) {
      case PlyType::Int8: value = load<std::int8_t>(b); break;
      case PlyType::UInt8: value = load<std::uint8_t>(b); break;
      case PlyType::Int16: value = load<std::int16_t>(b); break;
      case PlyType::UInt16: value = load<std::uint16_t>(b); break;
      case PlyType::Int32: value = load<std::int32_t>(b); break;
      case PlyType::UInt32: value = load<std::uint32_t>(b); break;
      case PlyType::Float32: value = load<float>(b); break;
      case PlyType::Float64: value = load<double>(b); break;
    }
    return true;
  }

 private:
  template <class T>
  static double load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
  }
  std::string_view body_;
  size_t pos_ = 0;
  bool swap_ = false;
};

template <class Values>
Status readPlyBody(Values& values, const PlyHeader& header, const std::string& path, size_t fileBytes,
                   TriMesh& mesh) {
  long long vertexCount = -1;
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") vertexCount = e.count;
  if (vertexCount < 0) return Status::error(StatusCode::FileUnreadable, path + ": no 'vertex' element in the header");

  std::string error;
  auto fail = [&](const std::string& element, long long item, const std::string& msg) {
    return Status::error(StatusCode::FileUnreadable, path + ": " + element + " " + std::to_string(item) + ": " + msg);
  };
  std::vector<int> polygon;
  for (const PlyElement& element : header.elements) {
    const bool isVertex = element.name == "vertex", isFace = element.name == "face";
    int coordinateOf[3] = {-1, -1, -1};  // property index of x, y, z
    int indexList = -1;
    for (int p = 0; p < static_cast<int>(element.properties.size()); ++p) {
      const PlyProperty& prop = element.properties[p];
      if (isVertex && !prop.isList && prop.name.size() == 1 && prop.name[0] >= 'x' && prop.name[0] <= 'z')
        coordinateOf[prop.name[0] - 'x'] = p;
      if (isFace && prop.isList && (prop.name == "vertex_indices" || prop.name == "vertex_index")) indexList = p;
    }
    if (isVertex && (coordinateOf[0] < 0 || coordinateOf[1] < 0 || coordinateOf[2] < 0))
      return Status::error(StatusCode::FileUnreadable, path + ": the vertex element has no x, y and z properties");
    if (isFace && indexList < 0)
      return Status::error(StatusCode::FileUnreadable, path + ": the face element has no vertex_indices list");
    // An element without properties takes no bytes: skip it whatever its count (a count of
    // 10^18 must not spin through empty items).
    if (element.properties.empty()) continue;
    if (isVertex) reserveAtMost(mesh.vertices, element.count, fileBytes, 3);
    if (isFace) reserveAtMost(mesh.faces, element.count, fileBytes, 4);

    for (long long item = 0; item < element.count; ++item) {
      double xyz[3] = {0, 0, 0};
      for (int p = 0; p < static_cast<int>(element.properties.size()); ++p) {
        const PlyProperty& prop = element.properties[p];
        double value = 0.0;
        if (!prop.isList) {
          if (!values.read(prop.type, value, error)) return fail(element.name, item, error);
          for (int c = 0; c < 3; ++c)
            if (coordinateOf[c] == p) xyz[c] = value;
          continue;
        }
        double count = 0.0;
        if (!values.read(prop.countType, count, error)) return fail(element.name, item, error);
        if (!(count >= 0) || count != std::floor(count))
          return fail(element.name, item, "list length " + std::to_string(count) + " is not a count");
        const bool isIndexList = p == indexList;
        if (isIndexList) polygon.clear();
        for (double k = 0; k < count; ++k) {
          if (!values.read(prop.type, value, error)) return fail(element.name, item, error);
          if (!isIndexList) continue;
          if (value != std::floor(value)) return fail(element.name, item, "vertex index is not an integer");
          if (value < 0 || value >= static_cast<double>(vertexCount))
            return Status::error(StatusCode::IndexOutOfRange,
                                 path + ": " + outOfRange(item, value, static_cast<size_t>(vertexCount)));
          polygon.push_back(static_cast<int>(value));
        }
        if (isIndexList && polygon.size() < 3)
          return fail(element.name, item, "has " + std::to_string(polygon.size()) + " vertices; need at least 3");
      }
      if (isVertex) mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
      if (isFace) fanTriangulate(polygon, mesh.faces);
    }
  }
  return Status::success();
}

}  // namespace

Status readPly(std::string_view text, const std::string& path, TriMesh& mesh) {
  PlyHeader header;
  if (Status s = readPlyHeader(text, path, header); !s.ok()) return s;
  const std::string_view body = text.substr(header.bodyOffset);
  if (header.encoding == PlyEncoding::Ascii) {
    const int headerLines = static_cast<int>(std::count(text.begin(), text.begin() + header.bodyOffset, '\n'));
    PlyAsciiValues values(body, headerLines);
    return readPlyBody(values, header, path, text.size(), mesh);
  }
  PlyBinaryValues values(body, header.encoding == PlyEncoding::BinaryBigEndian);
  return readPlyBody(values, header, path, text.size(), mesh);
}

std::string plyBytes(const TriMesh& mesh) {
  // Doubles so that positions survive the round trip exactly.
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by acd\nelement vertex " +
                    std::to_string(mesh.vertices.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(mesh.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + mesh.vertices.size() * 24 + mesh.faces.size() * 13);
  for (const Vec3& p : mesh.vertices)
    for (int c = 0; c < 3; ++c) appendLittleEndian(out, p[c]);
  for (const Face& f : mesh.faces) {
    out += static_cast<char>(3);
    for (int v : f) appendLittleEndian<std::int32_t>(out, v);
  }
  return out;
}

}  // namespace acd::format
