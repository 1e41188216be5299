// Closing the holes of an open surface so that it can be decomposed as a solid
// (Lien & Amato 2007 decompose solids; an open mesh is first made watertight).
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>

namespace acd {

struct HoleFilling {
  Status status;          // not ok: some hole could not be closed safely; `mesh` is then empty
  TriMesh mesh;           // closed; the input's vertices and faces come first, unchanged
  int holes = 0;          // boundary loops closed
  int addedFaces = 0;
  int addedVertices = 0;  // interior vertices of the patches (refinement)
  int unfairedHoles = 0;  // holes whose patch was triangulated and refined but could not be faired
};

/// Closes every boundary loop of a consistently oriented, edge-manifold triangle mesh with a
/// patch that is triangulated, refined to the density around the hole and faired (CGAL's
/// triangulate_refine_and_fair_hole), oriented like the surrounding faces. It refuses,
/// naming the hole, when a loop cannot be triangulated, when a patch makes the surface pass
/// through itself where it did not before, or when the result encloses no volume (a sheet
/// whose two sides would coincide).
HoleFilling fillHoles(const TriMesh& mesh);

}  // namespace acd
