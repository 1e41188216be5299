// The mesh a decomposition works on: the input with the detail that tau cannot see collapsed away,
// so that the cost follows the shape and tau, not how finely the input was triangulated.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

struct WorkingMesh {
  TriMesh mesh;               // its vertices are input vertices
  double tolerance = 0.0;     // what was asked: how far an input vertex may stand off the working surface
  double inputToWorking = 0.0;  // the largest such distance, measured on the result
  int collapses = 0;
};

/// Edge collapses on a closed, oriented, edge-manifold mesh, each edge onto one of its ends (the
/// one of less quadric error: Garland & Heckbert 1997), the cheapest first, so that every working
/// vertex is an input vertex and lies on the input. A collapse is made only if the surface stays a
/// closed manifold (the link condition), no face around it turns by more than about 70 degrees,
/// and every input vertex whose nearest face so far the collapse moves finds one of the new faces
/// within `tolerance`: every input vertex stays within `tolerance` of the working surface.
/// Deterministic: equal costs go by vertex index, so a mesh in canonical form simplifies alike in
/// every pose.
WorkingMesh simplifyWithin(const TriMesh& closed, double tolerance);

}  // namespace acd
