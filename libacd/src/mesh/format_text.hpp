// Reading and printing shared by the mesh file formats (io_off, io_obj, io_ply, io_stl): lines and
// tokens of a text, numbers that read back exactly, and the messages for bad indices.
#pragma once

#include <acd/mesh.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace acd::format {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

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
bool nextContentLine(LineReader& lines, Tokens& tokens);

/// Accepts "nan" and "inf" so that diagnosis, not the parser, reports non-finite coordinates.
bool parseDouble(std::string_view token, double& value);

bool parseInteger(std::string_view token, long long& value);

std::string quoted(std::string_view token);

void fanTriangulate(const std::vector<int>& polygon, std::vector<Face>& faces);

/// Reserves for a count read from a header, but never more than the file could hold:
/// a corrupt count must give a parse error, not an allocation failure.
template <class T>
void reserveAtMost(std::vector<T>& v, long long count, size_t fileBytes, size_t minBytesPerItem) {
  v.reserve(static_cast<size_t>(std::min<long long>(count, static_cast<long long>(fileBytes / minBytesPerItem + 1))));
}

std::string outOfRange(long long face, const std::string& index, size_t vertexCount);

std::string outOfRange(long long face, long long index, size_t vertexCount);

/// PLY indices arrive as doubles: 1e300 or inf has no integer to convert to.
std::string outOfRange(long long face, double index, size_t vertexCount);

void appendNumber(std::string& out, double value);

void appendInteger(std::string& out, long long value);

void appendVertexLine(std::string& out, const char* prefix, const Vec3& p);

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

}  // namespace acd::format
