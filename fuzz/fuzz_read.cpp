// libFuzzer harness for one mesh reader: the bytes are read as a file named ACD_FUZZ_NAME
// (its extension picks the reader). Any outcome but a Status or a well-formed mesh is a crash:
// the harness aborts when the reader's promises do not hold.
// With ACD_FUZZ_SCENE the first byte picks one of the scene formats read through assimp
// (kSceneNames) and the rest is the file: one harness, one smoke run, for five formats. Those
// are read as the acd command reads them, in a capped child (<sandbox/scene_reader.hpp>): assimp
// aborts and allocates without bound on some inputs, which must come back as refusals.
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>

#ifdef ACD_FUZZ_SCENE
#include <sandbox/scene_reader.hpp>
#endif

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#if !defined(ACD_FUZZ_NAME) && !defined(ACD_FUZZ_SCENE)
#error "define ACD_FUZZ_NAME, e.g. \"fuzz.off\", or ACD_FUZZ_SCENE"
#endif

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_read: broken promise: %s\n", what);
  std::abort();
}

/// A refusal is one line that names the file: what `acd` prints before exiting with code 2.
void checkRefusal(const acd::Status& status, const std::string& name) {
  require(!status.message.empty(), "an error without a message");
  require(status.message.find('\n') == std::string::npos, "an error message of several lines");
  require(status.message.compare(0, name.size(), name) == 0, "an error message that does not name the file");
}

void checkMesh(const acd::TriMesh& mesh) {
  require(!mesh.faces.empty(), "success with no faces");
  const long long n = static_cast<long long>(mesh.vertices.size());
  for (const acd::Face& f : mesh.faces)
    for (int v : f) require(v >= 0 && v < n, "a face index out of range after a successful read");
  // What `acd info` does next: the diagnosis must digest whatever the reader accepted.
  const acd::MeshDiagnosis d = acd::diagnose(mesh);
  require(d.faces == static_cast<int>(mesh.faces.size()), "diagnosis miscounts the faces");
  require(d.vertices == static_cast<int>(mesh.vertices.size()), "diagnosis miscounts the vertices");
}

#ifdef ACD_FUZZ_SCENE
// The order is part of the seeds' format (fuzz/make_seeds.py writes the selector byte).
constexpr const char* kSceneNames[] = {"fuzz.dae", "fuzz.gltf", "fuzz.glb", "fuzz.3mf", "fuzz.fbx"};
constexpr std::size_t kSceneCount = sizeof(kSceneNames) / sizeof(kSceneNames[0]);
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
#ifdef ACD_FUZZ_SCENE
  if (size == 0) return 0;
  const std::string name = kSceneNames[data[0] % kSceneCount];
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
#else
  const std::string name = ACD_FUZZ_NAME;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
#endif
#ifdef ACD_FUZZ_OBJECTS
  const acd::ObjObjects read = acd::readObjObjectsFromMemory(bytes, name);
  if (!read.status.ok()) {
    checkRefusal(read.status, name);
    require(read.objects.empty() && read.names.empty(), "objects left after a refusal");
    return 0;
  }
  require(read.objects.size() == read.names.size(), "one name per object");
  for (const acd::TriMesh& object : read.objects) checkMesh(object);
#elif defined(ACD_FUZZ_SCENE)
  // Short caps: an input that needs more is a refusal here, as a larger cap would make it one in acd.
  acdsandbox::SceneReaderCaps caps;
  caps.wallSeconds = 8;
  caps.memoryBytes = std::uint64_t(2) << 30;
  const acd::SceneMeshes scene = acdsandbox::readSceneFromMemoryIsolated(bytes, name, caps);
  acd::ReadResult read{scene.status, {}};
  if (scene.status.ok()) {
    require(scene.meshes.size() == scene.names.size(), "one name per placed mesh");
    read.mesh = acd::concatenate(scene.meshes);
  }
  if (!read.status.ok()) {
    checkRefusal(read.status, name);
    require(scene.meshes.empty(), "meshes left after a refusal");
    return 0;
  }
  checkMesh(read.mesh);
#else
  const acd::ReadResult read = acd::readMeshFromMemory(bytes, name);
  if (!read.status.ok()) {
    checkRefusal(read.status, name);
    require(read.mesh.vertices.empty() && read.mesh.faces.empty(), "a mesh left after a refusal");
    return 0;
  }
  checkMesh(read.mesh);
#endif
  return 0;
}
