// Regressions for reader bugs found while fuzzing (docs/FUZZING.md, "Findings"). Each input is
// the smallest file that showed the bug, built here; the readers must answer with a Status.
#include <acd/io.hpp>

#include <gtest/gtest.h>

#include <string>

using namespace acd;

namespace {

const std::string kPlyTriangleHeader =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

}  // namespace

// An element with no properties and a count of 10^11 made the PLY reader spin through empty
// items for hours. It takes no bytes, so it is skipped.
TEST(IoFuzzFindings, PlyElementWithoutPropertiesAndHugeCountIsSkipped) {
  for (const char* format : {"ascii", "binary_little_endian"}) {
    std::string bytes = std::string("ply\nformat ") + format + " 1.0\nelement nothing 100000000000\n" +
                        kPlyTriangleHeader;
    if (std::string(format) == "ascii") {
      bytes += "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    } else {
      const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
      bytes.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
      bytes += '\3';
      const int face[3] = {0, 1, 2};
      bytes.append(reinterpret_cast<const char*>(face), sizeof face);
    }
    const ReadResult r = readMeshFromMemory(bytes, "empty-element.ply");
    ASSERT_TRUE(r.status.ok()) << format << ": " << r.status.message;
    EXPECT_EQ(r.mesh.vertices.size(), 3u) << format;
    ASSERT_EQ(r.mesh.faces.size(), 1u) << format;
    EXPECT_EQ(r.mesh.faces[0], (Face{0, 1, 2})) << format;
  }
}

// An ASCII PLY index of inf (or 1e300) was converted to long long for the error message:
// undefined behaviour. The message now shows the value as read.
TEST(IoFuzzFindings, PlyInfiniteOrHugeIndexIsOutOfRange) {
  for (const char* index : {"inf", "1e300", "-inf", "9e18"}) {
    const std::string bytes =
        "ply\nformat ascii 1.0\n" + kPlyTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 " + index + "\n";
    const ReadResult r = readMeshFromMemory(bytes, "index.ply");
    EXPECT_EQ(r.status.code, StatusCode::IndexOutOfRange) << index << ": " << r.status.message;
    EXPECT_EQ(r.status.message.find('\n'), std::string::npos);
    EXPECT_NE(r.status.message.find("face 0 refers to vertex "), std::string::npos) << r.status.message;
    EXPECT_TRUE(r.mesh.faces.empty());
  }
}
