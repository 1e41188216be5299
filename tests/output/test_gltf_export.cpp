// writeGltf (libacd/src/output/gltf_export.cpp) read back with tinygltf: one named node per mesh,
// each with one triangle primitive whose float positions and 32-bit indices are the mesh's, as
// .glb and as .gltf with its buffer beside it; mismatched names and an unwritable path are a
// Status.
#include <acd/algo/gltf_export.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "helpers.hpp"

#include <cstring>
#include <filesystem>

using namespace acd;

namespace {

/// The mesh of node `i`: positions as read (floats widened) and indices.
TriMesh readBack(const tinygltf::Model& g, int i) {
  TriMesh out;
  const tinygltf::Primitive& p = g.meshes.at(g.nodes.at(i).mesh).primitives.at(0);
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  const tinygltf::Accessor& pos = g.accessors.at(p.attributes.at("POSITION"));
  const tinygltf::Accessor& idx = g.accessors.at(p.indices);
  EXPECT_EQ(pos.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(idx.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  const tinygltf::BufferView& pv = g.bufferViews.at(pos.bufferView);
  const tinygltf::BufferView& iv = g.bufferViews.at(idx.bufferView);
  const unsigned char* pdata = g.buffers.at(pv.buffer).data.data() + pv.byteOffset + pos.byteOffset;
  const unsigned char* idata = g.buffers.at(iv.buffer).data.data() + iv.byteOffset + idx.byteOffset;
  for (std::size_t v = 0; v < pos.count; ++v) {
    float xyz[3];
    std::memcpy(xyz, pdata + 12 * v, 12);
    out.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for (std::size_t k = 0; k + 2 < idx.count; k += 3) {
    std::uint32_t t[3];
    std::memcpy(t, idata + 4 * k, 12);
    out.faces.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  }
  return out;
}

}  // namespace

TEST(GltfExport, GlbAndGltfReadBackAsWritten) {
  acdtest::TempDir dir("gltf_export");
  const std::vector<TriMesh> meshes{shapes::box(Vec3(0.1, 0.2, 0.3), Vec3(1, 2, 3)), shapes::lShape()};
  const std::vector<std::string> names{"hull_000", "hull_001"};
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "glb" : "gltf");
    const std::string path = dir / (binary ? "hulls.glb" : "hulls.gltf");
    ASSERT_TRUE(writeGltf(path, meshes, names, binary, "hulls.bin").ok());
    if (!binary) EXPECT_TRUE(std::filesystem::exists(dir / "hulls.bin"));
    tinygltf::TinyGLTF loader;
    tinygltf::Model g;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromFile(&g, &err, &warn, path) : loader.LoadASCIIFromFile(&g, &err, &warn, path);
    ASSERT_TRUE(ok) << err;
    ASSERT_EQ(g.nodes.size(), meshes.size());
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      EXPECT_EQ(g.nodes[i].name, names[i]);
      const TriMesh back = readBack(g, static_cast<int>(i));
      EXPECT_EQ(back.faces, meshes[i].faces);
      ASSERT_EQ(back.vertices.size(), meshes[i].vertices.size());
      for (std::size_t v = 0; v < back.vertices.size(); ++v)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(back.vertices[v][c], static_cast<double>(static_cast<float>(meshes[i].vertices[v][c])));
    }
  }
}

TEST(GltfExport, MismatchedNamesAndUnwritablePathAreAStatus) {
  acdtest::TempDir dir("gltf_export_bad");
  const std::vector<TriMesh> meshes{shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))};
  const Status names = writeGltf(dir / "a.glb", meshes, {}, true);
  EXPECT_EQ(names.code, StatusCode::InvalidParameter);
  EXPECT_NE(names.message.find("names"), std::string::npos) << names.message;
  const Status path = writeGltf(dir / "no/such/folder/a.glb", meshes, {"a"}, true);
  EXPECT_FALSE(path.ok());
  EXPECT_EQ(path.message.find('\n'), std::string::npos);
}
