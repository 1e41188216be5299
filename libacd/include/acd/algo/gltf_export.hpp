// glTF 2.0 scenes of the hulls, written with tinygltf: one node per hull (named like the
// meshes), each with its own mesh of one triangle primitive (float positions, 32-bit indices).
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace acd {

/// `binary`: one .glb file; otherwise `path` (.gltf) plus its buffer, `bufferName` beside it.
Status writeGltf(const std::string& path, const std::vector<TriMesh>& meshes, const std::vector<std::string>& names,
                 bool binary, const std::string& bufferName = "hulls.bin");

}  // namespace acd
