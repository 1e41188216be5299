// STL (libacd/src/mesh/io_stl.cpp): binary round trip (float positions), ASCII corners merged,
// errors that name the line, truncated binary files.
#include "io_helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;
using namespace acdtest;

TEST(Io, StlRoundTripKeepsFloatPositionsAndFaces) {
  for (const auto& [name, mesh] : roundTripMeshes()) {
    SCOPED_TRACE(name);
    TempFile file(".stl");
    ASSERT_TRUE(writeMesh(file.path(), mesh).ok());
    EXPECT_EQ(std::filesystem::file_size(file.path()), 84 + 50 * mesh.faces.size());
    const ReadResult read = readMesh(file.path());
    ASSERT_TRUE(read.status.ok()) << read.status.message;
    // STL stores float corners per triangle: vertices come back merged, in order of first use.
    ASSERT_EQ(read.mesh.vertices.size(), mesh.vertices.size());
    ASSERT_EQ(read.mesh.faces.size(), mesh.faces.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.vertices[mesh.faces[f][k]];
        const Vec3& got = read.mesh.vertices[read.mesh.faces[f][k]];
        for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], throughFloat(p[c])) << "face " << f << " corner " << k;
      }
  }
}

TEST(Io, AsciiStlMergesCorners) {
  const ReadResult r = readText(".stl",
                                "solid two triangles\n"
                                "  facet normal 0 0 1\n"
                                "    outer loop\n"
                                "      vertex 0 0 0\n"
                                "      vertex 1 0 0\n"
                                "      vertex 1 1 0\n"
                                "    endloop\n"
                                "  endfacet\n"
                                "  facet normal 0 0 1\n"
                                "    outer loop\n"
                                "      vertex -0 0 0\n"
                                "      vertex 1 1 0\n"
                                "      vertex 0 1 0\n"
                                "    endloop\n"
                                "  endfacet\n"
                                "endsolid two triangles\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.mesh.vertices.size(), 4u);
  ASSERT_EQ(r.mesh.faces.size(), 2u);
  EXPECT_EQ(r.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(r.mesh.faces[1], (Face{0, 2, 3}));
}

TEST(Io, AsciiStlErrorNamesTheLine) {
  const ReadResult r = readText(".stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n");
  EXPECT_EQ(r.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(r.status.message.find("line 4: expected 3 coordinates"), std::string::npos) << r.status.message;
}

TEST(Io, TruncatedBinaryStl) {
  TempFile good(".stl");
  ASSERT_TRUE(writeMesh(good.path(), shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))).ok());
  std::ifstream in(good.path(), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ReadResult r = readText(".stl", bytes.substr(0, bytes.size() - 20));
  EXPECT_EQ(r.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(r.status.message.find("truncated"), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("12 triangles"), std::string::npos) << r.status.message;
}
