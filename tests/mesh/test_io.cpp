// readMesh and writeMesh (libacd/src/mesh/io.cpp): the dispatch by extension, exact round trips
// through every format, and what any reader says about a missing, empty or garbage file. Each
// format's own cases are in test_io_<format>.cpp.
#include "io_helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;
using namespace acdtest;

TEST(Io, TextAndPlyRoundTripsAreExact) {
  for (const char* ext : {".off", ".obj", ".ply", ".OFF"}) {
    for (const auto& [name, mesh] : roundTripMeshes()) {
      SCOPED_TRACE(std::string(name) + ext);
      TempFile file(ext);
      ASSERT_TRUE(writeMesh(file.path(), mesh).ok());
      const ReadResult read = readMesh(file.path());
      ASSERT_TRUE(read.status.ok()) << read.status.message;
      expectIdentical(mesh, read.mesh);
    }
  }
}

TEST(Io, NonFiniteCoordinatesSurviveWriting) {
  TriMesh mesh = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  mesh.vertices[2].x() = std::nan("");
  mesh.vertices[5].z() = -INFINITY;
  TempFile file(".off");
  ASSERT_TRUE(writeMesh(file.path(), mesh).ok());
  const ReadResult read = readMesh(file.path());
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  EXPECT_TRUE(std::isnan(read.mesh.vertices[2].x()));
  EXPECT_EQ(read.mesh.vertices[5].z(), -INFINITY);
}

TEST(Io, MissingFile) {
  const std::string path = (std::filesystem::temp_directory_path() / "acd_io_no_such_dir" / "mesh.off").string();
  const ReadResult r = readMesh(path);
  EXPECT_EQ(r.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(r.status.message.find(path), std::string::npos) << r.status.message;
  EXPECT_EQ(readObjObjects(path.substr(0, path.size() - 4) + ".obj").status.code, StatusCode::FileUnreadable);
  EXPECT_FALSE(writeMesh(path, shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))).ok());
}

TEST(Io, UnsupportedExtension) {
  TempFile file(".xyz");
  file.write("1 2 3\n");
  const ReadResult r = readMesh(file.path());
  EXPECT_EQ(r.status.code, StatusCode::UnsupportedFormat);
  EXPECT_NE(r.status.message.find(".xyz"), std::string::npos) << r.status.message;
  EXPECT_EQ(writeMesh(file.path(), shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))).code, StatusCode::UnsupportedFormat);
  EXPECT_EQ(readMesh("no_extension").status.code, StatusCode::UnsupportedFormat);
}

TEST(Io, GarbageText) {
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    const ReadResult r = readText(ext, "%%% this is not a mesh %%%\n\x01\x02\x03 garbage\n");
    EXPECT_FALSE(r.status.ok());
    EXPECT_EQ(r.status.code, StatusCode::FileUnreadable) << r.status.message;
    EXPECT_FALSE(r.status.message.empty());
    EXPECT_TRUE(r.mesh.empty());
  }
  const ReadResult off = readText(".off", "hello world\n");
  EXPECT_NE(off.status.message.find("line 1: expected OFF header, found 'hello'"), std::string::npos)
      << off.status.message;
}

TEST(Io, EmptyFile) {
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    const ReadResult r = readText(ext, "");
    EXPECT_EQ(r.status.code, StatusCode::EmptyMesh);
    EXPECT_NE(r.status.message.find("empty"), std::string::npos) << r.status.message;
  }
  // Vertices but no faces: nothing to decompose.
  EXPECT_EQ(readText(".obj", "v 0 0 0\n").status.code, StatusCode::EmptyMesh);
}
