#include <acd/io.hpp>
#include <acd/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace acd;

namespace {

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

ReadResult readText(const std::string& suffix, const std::string& text) {
  TempFile file(suffix);
  file.write(text);
  return readMesh(file.path());
}

void expectIdentical(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]) << "vertex " << i;
  for (size_t i = 0; i < a.faces.size(); ++i) EXPECT_EQ(a.faces[i], b.faces[i]) << "face " << i;
}

std::vector<std::pair<const char*, TriMesh>> roundTripMeshes() {
  return {{"icosphere", shapes::icosphere(Vec3(0.1, -0.2, 0.3), 1.7, 2)}, {"torus", shapes::torus(2.0, 0.5, 24, 12)}};
}

/// Rounds to float and back. Out of line on purpose: GCC 12.2 at -O2 (SLP vectorizer) turns an
/// inlined double->float->double round trip of adjacent coordinates into a plain copy
/// (with or without Eigen's cast<>), and the test would compare against unrounded values.
[[gnu::noinline]] double throughFloat(double x) {
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

}  // namespace

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

TEST(Io, OffWithQuadsColoursAndComments) {
  const ReadResult r = readText(".off",
                                "COFF # coloured\n"
                                "# a unit square pyramid\n"
                                "5 2 0\n"
                                "0 0 0 255 0 0 255\n"
                                "1 0 0 255 0 0 255\n"
                                "\n"
                                "1 1 0 255 0 0 255\n"
                                "0 1 0 255 0 0 255\n"
                                "0.5 0.5 +1e0 255 0 0 255\n"
                                "4 0 3 2 1 0.5 0.5 0.5\n"
                                "3 0 1 4\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.mesh.vertices.size(), 5u);
  EXPECT_EQ(r.mesh.vertices[4], Vec3(0.5, 0.5, 1.0));
  ASSERT_EQ(r.mesh.faces.size(), 3u);
  EXPECT_EQ(r.mesh.faces[0], (Face{0, 3, 2}));
  EXPECT_EQ(r.mesh.faces[1], (Face{0, 2, 1}));
  EXPECT_EQ(r.mesh.faces[2], (Face{0, 1, 4}));
}

TEST(Io, OffCountsOnTheHeaderLineAndNoff) {
  const ReadResult r = readText(".off", "NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.mesh.faces.size(), 1u);
}

TEST(Io, OffErrorsNameTheLine) {
  const ReadResult few = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(few.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(few.status.message.find("line 4: expected 3 coordinates"), std::string::npos) << few.status.message;

  const ReadResult range = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_EQ(range.status.code, StatusCode::IndexOutOfRange);
  EXPECT_NE(range.status.message.find("face 0 refers to vertex 3 but the file has 3 vertices"), std::string::npos)
      << range.status.message;

  const ReadResult shortFile = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_EQ(shortFile.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(shortFile.status.message.find("read 2 of 3 vertices"), std::string::npos) << shortFile.status.message;
}

TEST(Io, NanCoordinateInOffIsReadNotRejected) {
  const ReadResult r = readText(".off", "OFF\n3 1 0\nnan 0 0\n1 inf 0\n0 1 -Infinity\n3 0 1 2\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(std::isnan(r.mesh.vertices[0].x()));
  EXPECT_EQ(r.mesh.vertices[1].y(), INFINITY);
  EXPECT_EQ(r.mesh.vertices[2].z(), -INFINITY);
}

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
