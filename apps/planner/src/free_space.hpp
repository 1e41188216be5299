// The free space of a workspace: its bounding box minus the obstacles, as one closed mesh.
#pragma once

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace planner {

struct FreeSpace {
  bool ok = false;
  std::string error;      // why it failed, naming the obstacle where there is one
  acd::TriMesh mesh;      // closed, outward-oriented; may have several shells (cavities)
  std::string method;     // "corefinement" or "nef"
};

/// Workspace box minus the union of the obstacles, with exact arithmetic. Each obstacle must
/// be a closed mesh; parts outside the box are clipped away. Corefinement is tried first;
/// when an intermediate result would be non-manifold (obstacles touching along an edge) the
/// whole difference is redone with Nef polyhedra, which are slower but always valid.
FreeSpace buildFreeSpace(const acd::Box3& workspace, const std::vector<acd::TriMesh>& obstacles,
                         const std::vector<std::string>& names);

/// libacd decomposes every closed shell as a solid of its own, so an obstacle floating in the
/// free space (a cavity: a shell of negative volume) would not be seen as a hole. This cuts the
/// free space, by planes through its cavities, into pieces without any; each piece can then be
/// decomposed, and the cuts become openings like any other. A free space without cavities
/// comes back as one piece. On failure (never expected) returns no pieces and sets `error`.
std::vector<acd::TriMesh> cavityFreePieces(const acd::TriMesh& freeSpace, std::string& error);

}  // namespace planner
