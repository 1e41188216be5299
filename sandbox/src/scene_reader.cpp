// The child reads the scene with libacd and writes it into the pipe (pipe_codec.hpp): a status
// code and message, then per mesh its name, vertices (3 doubles each) and faces (3 int32 each).
// The parent decodes it; a child that crashed, hit a cap or wrote something malformed is a refusal naming the file.
#include <sandbox/scene_reader.hpp>

#include <sandbox/child_process.hpp>
#include <sandbox/pipe_codec.hpp>

#include <signal.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <system_error>

namespace acdsandbox {
namespace {

// assimp's working memory on honest files stays within a few dozen times the file's size;
// the floor covers small files with large embedded buffers, the slope large scenes.
constexpr std::uint64_t kMemoryFloor = std::uint64_t(4) << 30;
constexpr std::uint64_t kMemoryPerByte = 64;
constexpr double kSecondsFloor = 120.0;
constexpr double kSecondsPerMiB = 10.0;

std::string encode(const acd::SceneMeshes& scene) {
  PipeWriter w;
  w.put(static_cast<std::uint64_t>(scene.status.code));
  w.text(scene.status.message);
  w.put(static_cast<std::uint64_t>(scene.meshes.size()));
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const acd::TriMesh& mesh = scene.meshes[m];
    w.text(m < scene.names.size() ? scene.names[m] : std::string());
    w.put(static_cast<std::uint64_t>(mesh.vertices.size()));
    for (const acd::Vec3& v : mesh.vertices) {
      const double xyz[3] = {v.x(), v.y(), v.z()};
      w.put(xyz);
    }
    w.put(static_cast<std::uint64_t>(mesh.faces.size()));
    for (const acd::Face& f : mesh.faces) {
      const std::int32_t abc[3] = {f[0], f[1], f[2]};
      w.put(abc);
    }
  }
  return w.data();
}

bool decode(std::string_view bytes, acd::SceneMeshes& scene) {
  PipeReader r(bytes);
  std::uint64_t code = 0, meshes = 0;
  if (!r.get(code) || code > static_cast<std::uint64_t>(acd::StatusCode::InternalError)) return false;
  scene.status.code = static_cast<acd::StatusCode>(code);
  if (!r.text(scene.status.message) || !r.get(meshes)) return false;
  for (std::uint64_t m = 0; m < meshes; ++m) {
    acd::TriMesh mesh;
    std::string name;
    std::uint64_t n = 0;
    if (!r.text(name) || !r.get(n) || !r.fits(n, 3 * sizeof(double))) return false;
    mesh.vertices.resize(n);
    for (acd::Vec3& v : mesh.vertices) {
      double xyz[3] = {};  // (fits() above: the bytes are there)
      r.get(xyz);
      v = acd::Vec3(xyz[0], xyz[1], xyz[2]);
    }
    if (!r.get(n) || !r.fits(n, 3 * sizeof(std::int32_t))) return false;
    mesh.faces.resize(n);
    for (acd::Face& f : mesh.faces) {
      std::int32_t abc[3] = {};
      r.get(abc);
      for (int k = 0; k < 3; ++k) {
        if (abc[k] < 0 || static_cast<std::size_t>(abc[k]) >= mesh.vertices.size()) return false;
        f[k] = abc[k];
      }
    }
    scene.meshes.push_back(std::move(mesh));
    scene.names.push_back(std::move(name));
  }
  return r.left() == 0;
}

acd::SceneMeshes refused(const std::string& path, const std::string& why) {
  acd::SceneMeshes out;
  out.status = acd::Status::error(acd::StatusCode::FileUnreadable, path + ": cannot read: " + why);
  return out;
}

/// Runs `read` in a child under the caps (those left at zero derived from `bytes`, the file's size).
template <class Read>
acd::SceneMeshes isolated(const std::string& name, std::uint64_t bytes, SceneReaderCaps caps, Read&& read) {
  ChildOptions options;
  options.pipe = true;
  options.limits.memoryBytes = caps.memoryBytes > 0 ? caps.memoryBytes : kMemoryFloor + kMemoryPerByte * bytes;
  options.limits.wallSeconds =
      caps.wallSeconds > 0 ? caps.wallSeconds : kSecondsFloor + kSecondsPerMiB * static_cast<double>(bytes) / (1 << 20);
  // The callers are single-threaded when they read (the CLI reads before it decomposes), so the
  // child may allocate and run assimp. It dies by the signal of a crash, whatever handler the
  // caller installed (a fuzzer's, an interpreter's): the parent turns that into a refusal.
  const ChildOutcome child = runInChild(
      [&](int fd) {
        for (int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(s, SIG_DFL);
        return writeAll(fd, encode(read())) ? 0 : 1;
      },
      options);
  const std::string memory = std::to_string(options.limits.memoryBytes >> 20) + " MiB";
  if (!child.ok()) {
    if (child.end == ChildEnd::MemoryCap)
      return refused(name, "the scene reader (assimp) needed more than " + memory);
    return refused(name, "the scene reader (assimp) failed: " + child.describe(options.limits));
  }
  acd::SceneMeshes scene;
  if (!decode(child.data, scene)) return refused(name, "the scene reader's output was malformed (a bug)");
  const std::string& message = scene.status.message;
  if (!scene.status.ok() && message.size() >= 9 && message.compare(message.size() - 9, 9, "bad_alloc") == 0)
    return refused(name, "the scene reader (assimp) needed more than " + memory);
  return scene;
}

}  // namespace

acd::SceneMeshes readSceneIsolated(const std::string& path, SceneReaderCaps caps) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return acd::readScene(path);  // missing or unreadable: libacd says so, without a child
  return isolated(path, size, caps, [&] { return acd::readScene(path); });
}

acd::SceneMeshes readSceneFromMemoryIsolated(std::string_view data, const std::string& name, SceneReaderCaps caps) {
  return isolated(name, data.size(), caps, [&] { return acd::readSceneFromMemory(data, name); });
}

acd::ReadResult readModel(const std::string& path) {
  if (!acd::isSceneFormat(path)) return acd::readMesh(path);
  acd::SceneMeshes scene = readSceneIsolated(path);
  if (!scene.status.ok()) return {scene.status, {}};
  return {scene.status, acd::concatenate(scene.meshes)};
}

}  // namespace acdsandbox
