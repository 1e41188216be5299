// What the tests of the file formats share (test_io.cpp and test_io_<format>.cpp): a temporary
// file, reading a text as a mesh file, exact comparison, meshes for round trips, float rounding
// and big-endian bytes.
#pragma once

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace acdtest {

using namespace acd;

/// A per-test, per-process path in the temp directory, removed at the end of the test.
class TempFile {
 public:
  explicit TempFile(const std::string& suffix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = (std::filesystem::temp_directory_path() /
             ("acd_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()) + suffix))
                .string();
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  const std::string& path() const { return path_; }
  void write(const std::string& bytes) const {
    std::ofstream out(path_, std::ios::binary);
    out << bytes;
  }

 private:
  std::string path_;
};

inline ReadResult readText(const std::string& suffix, const std::string& text) {
  TempFile file(suffix);
  file.write(text);
  return readMesh(file.path());
}

inline void expectIdentical(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]) << "vertex " << i;
  for (size_t i = 0; i < a.faces.size(); ++i) EXPECT_EQ(a.faces[i], b.faces[i]) << "face " << i;
}

inline std::vector<std::pair<const char*, TriMesh>> roundTripMeshes() {
  return {{"icosphere", shapes::icosphere(Vec3(0.1, -0.2, 0.3), 1.7, 2)}, {"torus", shapes::torus(2.0, 0.5, 24, 12)}};
}

/// Rounds to float and back. Out of line on purpose: GCC 12.2 at -O2 (SLP vectorizer) turns an
/// inlined double->float->double round trip of adjacent coordinates into a plain copy
/// (with or without Eigen's cast<>), and the test would compare against unrounded values.
[[gnu::noinline]] inline double throughFloat(double x) {
  const float rounded = static_cast<float>(x);
  return rounded;
}

template <class T>
void appendBigEndian(std::string& out, T value) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof b);
  const std::uint16_t one = 1;
  if (*reinterpret_cast<const unsigned char*>(&one) == 1) std::reverse(b, b + sizeof b);
  out.append(reinterpret_cast<const char*>(b), sizeof b);
}

}  // namespace acdtest
