// Writes a soup as COLLADA through assimp's exporter, one mesh (and node) per piece, so that
// the planner reads it back through the same assimp path as third-party benchmark scenes.
#pragma once

#include "soup.hpp"

#include <string>

namespace scenes {

/// Writes `soup` to `path` (written to a temporary name, then renamed, so that a reader never
/// sees half a file). Returns an empty string on success, else the reason.
std::string writeCollada(const std::string& path, const Soup& soup);

}  // namespace scenes
