#pragma once
// How deep a solid's surface lies below its convex hull, straight through the inside: each
// vertex's distance to the nearest hull face plane. The paper's concavity (along the surface, to
// the bridge a pocket faces) is never smaller, so a depth above tau is a concavity above tau that
// no misled pocket measure can hide.
#include <acd/mesh.hpp>

namespace acd {

struct HullDepth {
  double distance = 0.0;  // the largest depth of a vertex below the hull's boundary
  int vertex = -1;        // the deepest vertex (the smaller index on a tie)
  int hullFace = -1;      // the hull face nearest to it
};

/// `hull` is the convex hull of `mesh`'s vertices. Each face's plane is placed at the support of
/// the hull's vertices along its normal, so that a thin face's rounded normal cannot cut the hull.
HullDepth deepestBelowHull(const TriMesh& mesh, const TriMesh& hull);

}  // namespace acd
