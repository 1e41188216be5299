// libFuzzer harness for one mesh reader: the bytes are read as a file named ACD_FUZZ_NAME
// (its extension picks the reader). Any outcome but a Status or a well-formed mesh is a crash:
// the harness aborts when the reader's promises do not hold.
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#ifndef ACD_FUZZ_NAME
#error "define ACD_FUZZ_NAME, e.g. \"fuzz.off\""
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string name = ACD_FUZZ_NAME;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
#ifdef ACD_FUZZ_OBJECTS
  const acd::ObjObjects read = acd::readObjObjectsFromMemory(bytes, name);
  if (!read.status.ok()) {
    checkRefusal(read.status, name);
    require(read.objects.empty() && read.names.empty(), "objects left after a refusal");
    return 0;
  }
  require(read.objects.size() == read.names.size(), "one name per object");
  for (const acd::TriMesh& object : read.objects) checkMesh(object);
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
