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

std::string outOfRange(long long face, const std::string& index, size_t vertexCount) {
  return "face " + std::to_string(face) + " refers to vertex " + index + " but the file has " +
         std::to_string(vertexCount) + " vertices";
}

std::string outOfRange(long long face, long long index, size_t vertexCount) {
  return outOfRange(face, std::to_string(index), vertexCount);
}

std::string outOfRange(long long face, double index, size_t vertexCount) {
  if (std::abs(index) < 9e18) return outOfRange(face, static_cast<long long>(index), vertexCount);
  char text[32];
  std::snprintf(text, sizeof text, "%g", index);
  return outOfRange(face, std::string(text), vertexCount);
}

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

}  // namespace acd::format
