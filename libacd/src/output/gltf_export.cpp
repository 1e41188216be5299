// glTF scenes of the hulls with tinygltf; see gltf_export.hpp.
#include <acd/algo/gltf_export.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>

namespace acd {

namespace {

template <class T>
void append(std::vector<unsigned char>& bytes, const T& value) {
  const auto* p = reinterpret_cast<const unsigned char*>(&value);
  bytes.insert(bytes.end(), p, p + sizeof(T));
}

}  // namespace

Status writeGltf(const std::string& path, const std::vector<TriMesh>& meshes, const std::vector<std::string>& names,
                 bool binary, const std::string& bufferName) {
  if (meshes.size() != names.size())
    return Status::error(StatusCode::InvalidParameter, path + ": " + std::to_string(meshes.size()) + " meshes but " +
                                                           std::to_string(names.size()) + " names");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "acd";
  tinygltf::Buffer buffer;
  tinygltf::Scene scene;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const TriMesh& m = meshes[i];
    if (m.faces.empty()) continue;
    // Positions (float, with the bounds glTF requires), then indices; each view 4-byte aligned.
    const std::size_t positionsAt = buffer.data.size();
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    for (const Vec3& v : m.vertices)
      for (int c = 0; c < 3; ++c) {
        const float x = static_cast<float>(v[c]);
        append(buffer.data, x);
        lo[c] = std::min(lo[c], static_cast<double>(x));
        hi[c] = std::max(hi[c], static_cast<double>(x));
      }
    const std::size_t indicesAt = buffer.data.size();
    for (const Face& f : m.faces)
      for (int v : f) append(buffer.data, static_cast<std::uint32_t>(v));

    tinygltf::BufferView positions;
    positions.buffer = 0;
    positions.byteOffset = positionsAt;
    positions.byteLength = indicesAt - positionsAt;
    positions.target = TINYGLTF_TARGET_ARRAY_BUFFER;
    tinygltf::BufferView indices;
    indices.buffer = 0;
    indices.byteOffset = indicesAt;
    indices.byteLength = buffer.data.size() - indicesAt;
    indices.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
    const int viewP = static_cast<int>(model.bufferViews.size());
    model.bufferViews.push_back(positions);
    model.bufferViews.push_back(indices);

    tinygltf::Accessor pa;
    pa.bufferView = viewP;
    pa.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    pa.type = TINYGLTF_TYPE_VEC3;
    pa.count = m.vertices.size();
    pa.minValues = lo;
    pa.maxValues = hi;
    tinygltf::Accessor ia;
    ia.bufferView = viewP + 1;
    ia.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    ia.type = TINYGLTF_TYPE_SCALAR;
    ia.count = 3 * m.faces.size();
    const int accP = static_cast<int>(model.accessors.size());
    model.accessors.push_back(pa);
    model.accessors.push_back(ia);

    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = accP;
    prim.indices = accP + 1;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = names[i];
    mesh.primitives.push_back(prim);
    tinygltf::Node node;
    node.name = names[i];
    node.mesh = static_cast<int>(model.meshes.size());
    model.meshes.push_back(mesh);
    scene.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(node);
  }
  if (!binary) buffer.uri = bufferName;
  model.buffers.push_back(buffer);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  // embedBuffers: a GLB holds its buffer; a .gltf gets it as the file `bufferName` beside it.
  // tinygltf reports success for a .glb it could not open (it does not check its stream), so the
  // file is removed first and must exist afterwards.
  std::error_code ec;
  std::filesystem::remove(path, ec);
  bool ok = false;
  try {
    ok = writer.WriteGltfSceneToFile(&model, path, false, binary, true, binary);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok || !std::filesystem::exists(path)) return Status::error(StatusCode::FileUnreadable, "cannot write " + path);
  if (!binary && !std::filesystem::exists(std::filesystem::path(path).parent_path() / bufferName))
    return Status::error(StatusCode::FileUnreadable, "cannot write " + bufferName + " beside " + path);
  return Status::success();
}

}  // namespace acd
