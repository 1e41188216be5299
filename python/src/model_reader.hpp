// How the module reads model files: as the acd command does, scene formats in a capped child
// process (<sandbox/scene_reader.hpp>), the other formats with libacd's own parsers.
#pragma once

#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#include <sandbox/scene_reader.hpp>

#include <string>

namespace acdpy {

inline acd::ReadResult readModel(const std::string& path) { return acdsandbox::readModel(path); }

inline acd::SceneMeshes readSceneModel(const std::string& path) { return acdsandbox::readSceneIsolated(path); }

}  // namespace acdpy
