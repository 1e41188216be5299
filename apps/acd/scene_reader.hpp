// Transitional: the planner compiles apps/acd/scene_reader.cpp and includes this header from
// here, without the sandbox's include folder. It forwards to the sandbox's reader, as acd's own
// here, without the sandbox's include folder (acd's main.cpp, in this folder, finds it first too). It
// forwards to the sandbox's reader, as acd's own
// <sandbox/scene_reader.hpp> itself.
#pragma once

#include "../../sandbox/include/sandbox/scene_reader.hpp"

namespace acdcli {

using acdsandbox::readModel;
using acdsandbox::readSceneIsolated;

}  // namespace acdcli
