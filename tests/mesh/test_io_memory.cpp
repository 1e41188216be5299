// Reading from memory (readMeshFromMemory, readObjObjectsFromMemory) gives what reading the same
// bytes from a file gives: same mesh, same refusal.
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace acd;

namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("acd_io_memory_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace

TEST(IoMemory, SameMeshAsFromFileInEveryFormat) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 12, 6);
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    const std::string path = tempPath(std::string("torus") + ext);
    ASSERT_TRUE(writeMesh(path, torus).ok()) << ext;
    const ReadResult fromFile = readMesh(path);
    const ReadResult fromMemory = readMeshFromMemory(bytesOf(path), path);
    std::filesystem::remove(path);
    ASSERT_TRUE(fromFile.status.ok()) << fromFile.status.message;
    ASSERT_TRUE(fromMemory.status.ok()) << fromMemory.status.message;
    EXPECT_EQ(fromMemory.mesh.vertices, fromFile.mesh.vertices) << ext;
    EXPECT_EQ(fromMemory.mesh.faces, fromFile.mesh.faces) << ext;
    EXPECT_EQ(fromMemory.mesh.faces.size(), torus.faces.size()) << ext;
  }
}

TEST(IoMemory, RefusalsNameTheGivenName) {
  const ReadResult empty = readMeshFromMemory("", "model.off");
  EXPECT_EQ(empty.status.code, StatusCode::EmptyMesh);
  EXPECT_EQ(empty.status.message, "model.off: file is empty");

  const ReadResult unknown = readMeshFromMemory("OFF\n0 0 0\n", "model.xyz");
  EXPECT_EQ(unknown.status.code, StatusCode::UnsupportedFormat);
  EXPECT_EQ(unknown.status.message.rfind("model.xyz: ", 0), 0u) << unknown.status.message;

  const ReadResult bad = readMeshFromMemory("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "in-memory.off");
  EXPECT_EQ(bad.status.code, StatusCode::IndexOutOfRange);
  EXPECT_EQ(bad.status.message.rfind("in-memory.off: line 6: ", 0), 0u) << bad.status.message;
  EXPECT_TRUE(bad.mesh.faces.empty() && bad.mesh.vertices.empty());
}

TEST(IoMemory, ObjectsAsFromFile) {
  const std::string text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no b\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n";
  const ObjObjects objects = readObjObjectsFromMemory(text, "hulls.obj");
  ASSERT_TRUE(objects.status.ok()) << objects.status.message;
  ASSERT_EQ(objects.objects.size(), 2u);
  EXPECT_EQ(objects.names, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(objects.objects[1].vertices[0], Vec3(5, 0, 0));
  EXPECT_EQ(objects.objects[1].faces[0], (Face{0, 1, 2}));

  EXPECT_EQ(readObjObjectsFromMemory(text, "hulls.off").status.code, StatusCode::UnsupportedFormat);
  EXPECT_EQ(readObjObjectsFromMemory("", "hulls.obj").status.code, StatusCode::EmptyMesh);
}
