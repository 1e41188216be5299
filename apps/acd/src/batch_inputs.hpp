// acd batch: which meshes a batch decomposes, and the name each gets under OUT/.
#pragma once

#include <string>
#include <vector>

namespace acdcli {

struct BatchInput {
  std::string name;     // unique; the mesh's results go to OUT/NAME/
  std::string path;     // as given, or joined to its folder or manifest
  std::string problem;  // non-empty when the file cannot be read (a manifest entry that is missing, ...)
};

/// Files with a mesh extension (.off .obj .ply .stl, any case) are meshes, folders are searched
/// recursively for such files, any other file is a manifest: one path per line (relative to the
/// manifest's folder; blank lines and lines starting with '#' skipped), each a mesh or a folder.
/// A mesh reached twice is kept once. Names are the file name without extension (for a folder,
/// the path inside it, '/' written "__"), made unique with "-2", "-3", ... in path order.
/// Returns false, with `error`, when a command-line INPUT does not exist.
bool resolveBatchInputs(const std::vector<std::string>& inputs, std::vector<BatchInput>& meshes, std::string& error);

bool isMeshFile(const std::string& path);

}  // namespace acdcli
