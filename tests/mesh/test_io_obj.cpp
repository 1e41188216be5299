// OBJ (libacd/src/mesh/io_obj.cpp): negative indices and slash forms, index errors, objects and
// groups (readObjObjects, writeObjObjects).
#include "io_helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;
using namespace acdtest;

TEST(Io, ObjNegativeIndicesAndSlashForms) {
  const ReadResult r = readText(".obj",
                                "# cube corner\r\n"
                                "mtllib x.mtl\n"
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvn 0 0 1\n"
                                "usemtl red\ns off\n"
                                "f 1/1/1 2/1/1 3/1/1\r\n"
                                "f -4//1 -2//1 -1//1\n"
                                "v 0 0 1\n"
                                "f 1/1 2/1 -1/1 4\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.mesh.vertices.size(), 5u);
  ASSERT_EQ(r.mesh.faces.size(), 4u);
  EXPECT_EQ(r.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(r.mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_EQ(r.mesh.faces[2], (Face{0, 1, 4}));
  EXPECT_EQ(r.mesh.faces[3], (Face{0, 4, 3}));
}

TEST(Io, ObjIndexErrors) {
  const ReadResult zero = readText(".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  EXPECT_EQ(zero.status.code, StatusCode::IndexOutOfRange);
  EXPECT_NE(zero.status.message.find("line 4"), std::string::npos) << zero.status.message;

  const ReadResult past = readText(".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n");
  EXPECT_EQ(past.status.code, StatusCode::IndexOutOfRange);
  EXPECT_NE(past.status.message.find("line 5: face 1 refers to vertex 7 but the file has 3 vertices"),
            std::string::npos)
      << past.status.message;

  const ReadResult negative = readText(".obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -4\n");
  EXPECT_EQ(negative.status.code, StatusCode::IndexOutOfRange);
}

TEST(Io, ObjectsRoundTrip) {
  const std::vector<TriMesh> meshes = {shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                       shapes::icosphere(Vec3(3, 0, 0), 1.0, 1),
                                       shapes::box(Vec3(-2, -2, -2), Vec3(-1, -0.5, -1.25))};
  const std::vector<std::string> names = {"hull_0", "ball with spaces", ""};
  TempFile file(".obj");
  ASSERT_TRUE(writeObjObjects(file.path(), meshes, names).ok());
  const ObjObjects read = readObjObjects(file.path());
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  ASSERT_EQ(read.objects.size(), 3u);
  EXPECT_EQ(read.names, (std::vector<std::string>{"hull_0", "ball with spaces", "object_2"}));
  for (size_t i = 0; i < meshes.size(); ++i) expectIdentical(meshes[i], read.objects[i]);

  // The same file read as one mesh holds everything.
  const ReadResult whole = readMesh(file.path());
  ASSERT_TRUE(whole.status.ok());
  EXPECT_EQ(whole.mesh.faces.size(), meshes[0].faces.size() + meshes[1].faces.size() + meshes[2].faces.size());

  EXPECT_EQ(writeObjObjects(file.path(), meshes, {"a"}).code, StatusCode::InvalidParameter);
}

TEST(Io, ObjObjectsWithUngroupedFacesAndGroups) {
  TempFile file(".obj");
  file.write(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\n"
      "f 1 2 3\n"  // before any group: an unnamed object
      "o first\ng first_group\n"
      "f 1 2 4\nf 2 3 4\n"
      "g second\n"
      "f 5 4 3\n"
      "o trailing\n");
  const ObjObjects read = readObjObjects(file.path());
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  ASSERT_EQ(read.objects.size(), 3u);
  EXPECT_EQ(read.names, (std::vector<std::string>{"", "first_group", "second"}));
  EXPECT_EQ(read.objects[0].vertices.size(), 3u);
  EXPECT_EQ(read.objects[1].vertices.size(), 4u);
  EXPECT_EQ(read.objects[1].faces.size(), 2u);
  // Vertices are compacted per object, keeping file order: 3, 4, 5 become 0, 1, 2.
  ASSERT_EQ(read.objects[2].vertices.size(), 3u);
  EXPECT_EQ(read.objects[2].vertices[2], Vec3(5, 5, 5));
  EXPECT_EQ(read.objects[2].faces[0], (Face{2, 1, 0}));
}
