// Skeletons of two meshes that share their vertices (a mesh and a deformation of it: same
// vertices, same faces, moved) matched through those vertices rather than by graph shape: the
// edit distance of that matching says how much the structure changed, where the plain graph edit
// distance also says how well a search did on look-alike nodes.
#pragma once

#include <acd/mesh.hpp>
#include <vector>

#include "graph.hpp"

namespace skeleton {

/// For each vertex of `mesh`, the component (a piece of a decomposition of `mesh`) it is a corner
/// of: cutting keeps the input's vertices, so one lies within 1e-6 of the diagonal (the lowest
/// index when it lies on a cut, in several). A vertex no component has (a repair moved it) goes
/// to the hull it lies deepest in (the least largest signed distance to a facet's plane).
std::vector<int> componentOfVertices(const acd::TriMesh& mesh, const std::vector<acd::TriMesh>& components,
                                     const std::vector<acd::TriMesh>& hulls);

/// Node map from skeleton `a` to skeleton `b` (as editPathCost takes it). Part nodes: the parts of
/// a and b (vertex -> part in each) paired to share the most vertices (a maximum-weight
/// assignment); a part sharing none with its pair is deleted. Cut nodes (degree 2, between two
/// parts): to the cut node of b between the images of its two parts, if there is one.
std::vector<int> correspondenceMap(const Graph& a, const std::vector<int>& vertexPartA, const Graph& b,
                                   const std::vector<int>& vertexPartB);

/// The same map carried to the degree-2 contractions of a and b: a kept node goes where its image
/// is kept, to deletion where it is not.
std::vector<int> contractedMap(const Contraction& a, const Contraction& b, const std::vector<int>& map, int nodesOfB);

}  // namespace skeleton
