// Cutting a closed solid by a plane into closed solids (the cross-section is capped).
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/plane.hpp>

#include <string>
#include <vector>

namespace acd {

struct CutResult {
  bool ok = false;
  std::string error;             // why the cut failed (the caller may try a nudged plane)
  std::vector<TriMesh> below;    // edge-connected closed pieces with normal . x <= offset
  std::vector<TriMesh> above;
};

/// Splits a closed, outward-oriented mesh. Vertices within `snap` of the plane
/// count as on it (they are kept where they are, not moved), so no sliver
/// triangles are made; faces lying in the plane go to the side their normal
/// points away from. Each cross-section is triangulated once (constrained
/// Delaunay, exact predicates) and shared by both sides with opposite
/// orientations, so the pieces' volumes add up to the input's. Fails cleanly
/// (ok = false) when the section is not a set of simple, disjoint loops.
///
/// With `near`, the section region nearest that point is cut, and any other region with at least
/// a tenth of the mesh's volume on each side; across the rest the surface stays whole (a plane
/// through a hand's palm then leaves the fingertips on). When that would make a piece meet itself
/// across a cut region (the plane opens a handle), every region is cut.
CutResult cutByPlane(const TriMesh& mesh, const Plane& plane, double snap = 1e-10, const Vec3* near = nullptr);

}  // namespace acd
