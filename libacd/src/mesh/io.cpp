// Mesh files. Hand-written parsers over the whole file in memory: input meshes
// can have millions of faces, and bad input must come back as a Status naming
// the line or element, never as an exception.
#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
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

// ---------------------------------------------------------------- text scanning

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Lines of a text, without end-of-line and without `#` comments, counted from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text, bool stripComments = true)
      : text_(text), stripComments_(stripComments) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    if (stripComments_) {
      const size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
    }
    return true;
  }

  int number() const { return number_; }
  size_t offset() const { return std::min(pos_, text_.size()); }

 private:
  std::string_view text_;
  bool stripComments_;
  size_t pos_ = 0;
  int number_ = 0;
};

/// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line = {}) : rest_(line) {}

  bool next(std::string_view& token) {
    size_t i = 0;
    while (i < rest_.size() && isBlank(rest_[i])) ++i;
    if (i == rest_.size()) {
      rest_ = {};
      return false;
    }
    size_t j = i;
    while (j < rest_.size() && !isBlank(rest_[j])) ++j;
    token = rest_.substr(i, j - i);
    rest_ = rest_.substr(j);
    return true;
  }

  /// What is left of the line, trimmed: object names may contain spaces.
  std::string_view rest() const {
    size_t i = 0, j = rest_.size();
    while (i < j && isBlank(rest_[i])) ++i;
    while (j > i && isBlank(rest_[j - 1])) --j;
    return rest_.substr(i, j - i);
  }

 private:
  std::string_view rest_;
};

/// Reads the first content line (skipping blank and comment-only lines).
bool nextContentLine(LineReader& lines, Tokens& tokens) {
  std::string_view line;
  while (lines.next(line)) {
    tokens = Tokens(line);
    Tokens probe(line);
    std::string_view token;
    if (probe.next(token)) return true;
  }
  return false;
}

/// Accepts "nan" and "inf" so that diagnosis, not the parser, reports non-finite coordinates.
bool parseDouble(std::string_view token, double& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    // from_chars leaves the value unset; strtod gives +-HUGE_VAL or 0 like other readers do.
    const std::string copy(token);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return ec == std::errc() && ptr == last && first != last;
}

bool parseInteger(std::string_view token, long long& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last && first != last;
}

std::string quoted(std::string_view token) {
  constexpr size_t kMax = 40;  // binary garbage must not flood the message
  std::string out = "'";
  for (char c : token.substr(0, kMax)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  if (token.size() > kMax) out += "...";
  return out + "'";
}

void fanTriangulate(const std::vector<int>& polygon, std::vector<Face>& faces) {
  for (size_t i = 1; i + 1 < polygon.size(); ++i) faces.push_back({polygon[0], polygon[i], polygon[i + 1]});
}

/// Reserves for a count read from a header, but never more than the file could hold:
/// a corrupt count must give a parse error, not an allocation failure.
template <class T>
void reserveAtMost(std::vector<T>& v, long long count, size_t fileBytes, size_t minBytesPerItem) {
  v.reserve(static_cast<size_t>(std::min<long long>(count, static_cast<long long>(fileBytes / minBytesPerItem + 1))));
}

std::string outOfRange(long long face, const std::string& index, size_t vertexCount) {
  return "face " + std::to_string(face) + " refers to vertex " + index + " but the file has " +
         std::to_string(vertexCount) + " vertices";
}

std::string outOfRange(long long face, long long index, size_t vertexCount) {
  return outOfRange(face, std::to_string(index), vertexCount);
}

/// PLY indices arrive as doubles: 1e300 or inf has no integer to convert to.
std::string outOfRange(long long face, double index, size_t vertexCount) {
  if (std::abs(index) < 9e18) return outOfRange(face, static_cast<long long>(index), vertexCount);
  char text[32];
  std::snprintf(text, sizeof text, "%g", index);
  return outOfRange(face, std::string(text), vertexCount);
}

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

// ---------------------------------------------------------------- OFF

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

// ---------------------------------------------------------------- OBJ

struct ObjGroup {
  std::string name;
  size_t firstFace = 0;
};

struct ObjFile {
  TriMesh mesh;
  std::vector<ObjGroup> groups;  // in file order; faces before any `o`/`g` form an unnamed group
};

bool looksLikeKeyword(std::string_view token) {
  if (token.empty() || !std::isalpha(static_cast<unsigned char>(token[0]))) return false;
  return std::all_of(token.begin(), token.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

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

// ---------------------------------------------------------------- PLY

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

// ---------------------------------------------------------------- STL

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

Status readStl(std::string_view data, const std::string& path, TriMesh& mesh) {
  if (looksLikeAsciiStl(data)) return readAsciiStl(data, path, mesh);
  return readBinaryStl(data, path, mesh);
}

// ---------------------------------------------------------------- writing

void appendNumber(std::string& out, double value) {
  // Shortest text that reads back to the same double: exact round trips, small files.
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void appendInteger(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void appendVertexLine(std::string& out, const char* prefix, const Vec3& p) {
  out += prefix;
  for (int c = 0; c < 3; ++c) {
    if (c > 0) out += ' ';
    appendNumber(out, p[c]);
  }
  out += '\n';
}

template <class T>
void appendLittleEndian(std::string& out, T value) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof b);
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  if (first != 1) std::reverse(b, b + sizeof b);
  out.append(reinterpret_cast<const char*>(b), sizeof b);
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
      case Format::Off: s = readOff(data, name, result.mesh); break;
      case Format::Obj: {
        ObjFile obj;
        s = readObj(data, name, obj);
        result.mesh = std::move(obj.mesh);
        break;
      }
      case Format::Ply: s = readPly(data, name, result.mesh); break;
      case Format::Stl: s = readStl(data, name, result.mesh); break;
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
      case Format::Off: return writeWholeFile(path, offText(mesh));
      case Format::Obj: {
        std::string out;
        appendObjBody(out, mesh, 0);
        return writeWholeFile(path, out);
      }
      case Format::Ply: return writeWholeFile(path, plyBytes(mesh));
      case Format::Stl: return writeWholeFile(path, stlBytes(mesh));
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
    appendObjBody(out, meshes[i], firstVertex);
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
    ObjFile obj;
    if (Status s = readObj(data, path, obj); !s.ok()) return s;
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
