// PLY (libacd/src/mesh/io_ply.cpp): ASCII with extra properties and elements, binary big-endian,
// out-of-range indices and truncation.
#include "io_helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;
using namespace acdtest;

TEST(Io, AsciiPlyWithExtraPropertiesAndElements) {
  const ReadResult r = readText(".ply",
                                "ply\r\n"
                                "format ascii 1.0\n"
                                "comment made by hand\n"
                                "element vertex 4\n"
                                "property float x\n"
                                "property float y\n"
                                "property float z\n"
                                "property uchar red\n"
                                "property list uchar float extra\n"
                                "element face 2\n"
                                "property uchar flags\n"
                                "property list uchar int vertex_indices\n"
                                "property float quality\n"
                                "element edge 1\n"
                                "property int vertex1\n"
                                "property int vertex2\n"
                                "end_header\n"
                                "0 0 0 255 0\n"
                                "1 0 0 255 2 7 8\n"
                                "1 1 0.5 255 1 9\n"
                                "0 1 -0.25 0 0\n"
                                "7 4 0 1 2 3 0.5\n"
                                "7 3 3 2 1 1.5\n"
                                "0 1\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.mesh.vertices.size(), 4u);
  EXPECT_EQ(r.mesh.vertices[2], Vec3(1, 1, 0.5));
  EXPECT_EQ(r.mesh.vertices[3], Vec3(0, 1, -0.25));
  ASSERT_EQ(r.mesh.faces.size(), 3u);
  EXPECT_EQ(r.mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_EQ(r.mesh.faces[2], (Face{3, 2, 1}));
}

TEST(Io, PlyIndexOutOfRangeAndTruncation) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar uint vertex_index\nend_header\n";
  const ReadResult range = readText(".ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  EXPECT_EQ(range.status.code, StatusCode::IndexOutOfRange);
  EXPECT_NE(range.status.message.find("face 0 refers to vertex 5 but the file has 3 vertices"), std::string::npos)
      << range.status.message;
  const ReadResult truncated = readText(".ply", header + "0 0 0\n1 0 0\n0 1\n");
  EXPECT_EQ(truncated.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(truncated.status.message.find("vertex 2"), std::string::npos) << truncated.status.message;
}

TEST(Io, BinaryBigEndianPlySkipsOtherProperties) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\n"
      "element vertex 3\nproperty float x\nproperty uchar red\nproperty float y\nproperty double z\n"
      "element material 1\nproperty list uchar short ids\n"
      "element face 1\nproperty list uint uint vertex_indices\nproperty int flags\n"
      "end_header\n";
  const float xy[3][2] = {{0.f, 0.f}, {1.5f, 0.f}, {0.f, -2.f}};
  for (int v = 0; v < 3; ++v) {
    appendBigEndian(bytes, xy[v][0]);
    appendBigEndian<std::uint8_t>(bytes, 200);
    appendBigEndian(bytes, xy[v][1]);
    appendBigEndian(bytes, 0.125 * v);
  }
  appendBigEndian<std::uint8_t>(bytes, 2);
  appendBigEndian<std::int16_t>(bytes, -1);
  appendBigEndian<std::int16_t>(bytes, 300);
  appendBigEndian<std::uint32_t>(bytes, 3);
  for (std::uint32_t i : {2u, 1u, 0u}) appendBigEndian(bytes, i);
  appendBigEndian<std::int32_t>(bytes, 42);
  const ReadResult r = readText(".ply", bytes);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.mesh.vertices.size(), 3u);
  EXPECT_EQ(r.mesh.vertices[1], Vec3(1.5, 0, 0.125));
  EXPECT_EQ(r.mesh.vertices[2], Vec3(0, -2, 0.25));
  ASSERT_EQ(r.mesh.faces.size(), 1u);
  EXPECT_EQ(r.mesh.faces[0], (Face{2, 1, 0}));

  const ReadResult truncated = readText(".ply", bytes.substr(0, bytes.size() - 3));
  EXPECT_EQ(truncated.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(truncated.status.message.find("face 0"), std::string::npos) << truncated.status.message;
}
