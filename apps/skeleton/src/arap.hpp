// As-rigid-as-possible surface deformation (Sorkine & Alexa 2007) with CGAL's
// `Surface_mesh_deformation`: a handle moved rigidly, a free region around it that follows
// as rigidly as it can, and everything else fixed.
#pragma once

#include "graph.hpp"

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace skeleton {

/// The handle is rotated by `angleDegrees` about the line through `pivot` along `axis`.
struct ArapRequest {
  std::vector<int> handle;  // vertex ids moved rigidly
  std::vector<int> region;  // vertex ids free to move (the handle may or may not be listed)
  Vec3 pivot = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double angleDegrees = 0.0;
  int iterations = 10;      // ARAP local/global iterations
};

struct ArapResult {
  bool ok = false;
  std::string error;
  acd::TriMesh mesh;        // same vertices and faces, moved
  double seconds = 0.0;
};

/// Deforms a closed triangle mesh. Never throws.
ArapResult arapDeform(const acd::TriMesh& mesh, const ArapRequest& request);

}  // namespace skeleton
