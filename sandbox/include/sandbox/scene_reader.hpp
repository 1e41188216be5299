// Scene files (glTF, GLB, COLLADA, 3MF, FBX) read in a child process. They go through assimp, a
// system library we cannot fix: fuzzing found a 1 KB COLLADA file on which it allocates 19 GB
// over two minutes before failing (docs/FUZZING.md). Run in a child under a memory and a time
// cap, such a file costs a second and comes back as a one-line refusal, as does a crash inside
// assimp. The other formats are read in-process by libacd's own parsers.
#pragma once

#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace acdsandbox {

/// acd::readMesh, with scene formats read in a capped child process (every placed mesh merged).
acd::ReadResult readModel(const std::string& path);

/// Caps on the reading child; zero: derived from the file's size (see scene_reader.cpp).
struct SceneReaderCaps {
  double wallSeconds = 0;
  std::uint64_t memoryBytes = 0;
};

/// acd::readScene in a capped child process: every placed mesh apart (--per-mesh).
acd::SceneMeshes readSceneIsolated(const std::string& path, SceneReaderCaps caps = {});

/// acd::readSceneFromMemory in a capped child process (the fuzz harness's way in).
acd::SceneMeshes readSceneFromMemoryIsolated(std::string_view data, const std::string& name, SceneReaderCaps caps = {});

}  // namespace acdsandbox
