// How acd reads model files, as the Python module does: the scene formats (glTF, GLB, COLLADA,
// 3MF, FBX) in a capped child process (sandbox/scene_reader), the others with libacd's parsers.
#pragma once

#include <sandbox/scene_reader.hpp>

namespace acdcli {

using acdsandbox::readModel;
using acdsandbox::readSceneIsolated;

}  // namespace acdcli
