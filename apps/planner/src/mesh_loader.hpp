// Mesh files for obstacles and robots: libacd's OFF/OBJ/PLY/STL reader, and assimp for
// COLLADA (.dae) and the other formats motion-planning benchmark environments come in.
#pragma once

#include <acd/mesh.hpp>

#include <string>

namespace planner {

struct LoadedMesh {
  bool ok = false;
  std::string error;  // names the file
  acd::TriMesh mesh;  // all meshes of the file, scene transforms applied, identical corners merged
};

LoadedMesh loadMeshFile(const std::string& path);

}  // namespace planner
