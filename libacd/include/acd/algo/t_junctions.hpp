// T-junctions: a vertex of one side of a seam lying on an edge of the other side. CAD exporters
// mesh each face of a part on its own, so along a seam one side may have a long edge where the
// other has the same edge in pieces: a crack of zero width that no hole filling can close (the
// "hole" has no area). Splitting the long edge at the vertices lying on it makes the two sides
// match edge for edge, and the seam closes without moving any point.
#pragma once

#include <acd/mesh.hpp>
#include <vector>

namespace acd {

struct TJunctionSplit {
  std::vector<Face> faces;  // the faces, each split one replaced by its fan in place
  int splitEdges = 0;       // boundary edges split
  int splitVertices = 0;    // vertices they were split at
};

/// Splits every boundary edge (used by exactly one face) at the boundary vertices lying on it:
/// within `tolerance` of the segment and farther than `tolerance` from both its ends. The face
/// becomes a fan from its third corner, in the face's orientation; edges split again through
/// later fans (a face with cracks on two sides) are handled in further rounds. Vertices keep
/// their indices; no vertex is added or moved.
TJunctionSplit splitTJunctions(const std::vector<Vec3>& vertices, const std::vector<Face>& faces, double tolerance);

}  // namespace acd
