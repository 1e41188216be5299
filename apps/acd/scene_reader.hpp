// Transitional: the planner compiles apps/acd/scene_reader.cpp and includes this header from
// here, without the sandbox's include folder (acd's main.cpp, in this folder, finds it first
// too). It forwards to the sandbox's reader, as acd's own src/scene_reader.hpp does; both files
// go once the planner links acd_sandbox and includes <sandbox/scene_reader.hpp> itself.
#pragma once

#include "../../sandbox/include/sandbox/scene_reader.hpp"

namespace acdcli {

using acdsandbox::readModel;
using acdsandbox::readSceneIsolated;

}  // namespace acdcli
