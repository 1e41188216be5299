// How the module reads model files: as the acd command does (scene formats in a capped child
// process, apps/acd/scene_reader.hpp) when built with the apps, else with libacd directly.
#pragma once

#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#ifdef ACD_ISOLATED_SCENES
#include "scene_reader.hpp"
#endif

#include <string>

namespace acdpy {

inline acd::ReadResult readModel(const std::string& path) {
#ifdef ACD_ISOLATED_SCENES
  return acdcli::readModel(path);
#else
  return acd::readMesh(path);
#endif
}

inline acd::SceneMeshes readSceneModel(const std::string& path) {
#ifdef ACD_ISOLATED_SCENES
  return acdcli::readSceneIsolated(path);
#else
  return acd::readScene(path);
#endif
}

}  // namespace acdpy
