// Concavity of a closed polyhedron (Lien & Amato 2007, Section 4.1 and Appendix A).
//
// Bridges are patches of convex-hull facets, clustered so that every facet of a
// patch lies within epsilon of the patch's supporting plane (a hull facet plane,
// so the plane is tangent to the hull). Each patch's boundary edges are projected
// onto the surface with shortest paths; the faces they enclose form the patch's
// pocket. The concavity of a vertex is its distance to the supporting plane of its
// pocket's bridge, and the concavity of the model is the largest vertex concavity.
#pragma once

#include <acd/algo/bridge.hpp>
#include <acd/algo/handles.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/algo/hull.hpp>
#include <acd/mesh.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace acd {

struct ConcavityOptions {
  double epsilon = 0.025;     // bridge clustering tolerance (normalised units); <= 0: one bridge per hull facet
  int lloydIterations = 4;    // Lloyd relaxation rounds after Algorithm 2 seeds the clusters
  /// Mesh edges (edgeKey) that pockets may not grow across, besides the projected bridge
  /// boundaries: the handle cuts of Section 5, so that on a surface of genus > 0 every
  /// pocket is bounded by a single bridge.
  std::vector<std::uint64_t> barrierEdges;
};

/// Projection of one hull edge between two different bridges onto the surface.
struct ProjectedEdge {
  int leftBridge = -1;           // bridge on the left of the hull edge (seen from outside)
  int rightBridge = -1;
  std::vector<int> path;         // mesh vertices, from the hull edge's first to its second end
};

struct ConcavityMap {
  ConvexHull hull;
  std::vector<Bridge> bridges;
  std::vector<ProjectedEdge> projections;
  std::vector<int> facePocket;           // mesh face -> bridge whose pocket holds it
  std::vector<double> vertexConcavity;   // estimated (bridge-patch) concavity, >= 0
  std::vector<int> vertexBridge;         // bridge realising vertexConcavity
  std::vector<double> facetConcavity;    // per-facet concavity: to the nearest facet plane of the same patch
  int bridgeEstimate = 0;                // Algorithm 2's count before Lloyd and refinement
  int refinements = 0;                   // patches split to keep Observation 4.1 within epsilon
  std::vector<HandleCut> handleCuts;     // Section 5: barriers found on a surface of genus > 0
  std::vector<HandleCut> pocketDivides;  // barriers dividing pockets still ringed by several bridges after that
  int sharedPockets = 0;                 // pockets still ringed by loops of several bridges at the end
  double concavity = 0.0;                // max vertex concavity
  int notch = -1;                        // vertex realising it
};

/// Measures concavity. `mesh` must be closed, oriented outward and in normalised units.
ConcavityMap measureConcavity(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityOptions& options);

/// Appendix A, Algorithm 2: number of bridges needed to cover the hull with tolerance epsilon.
/// Also returns the seed facets it picked (largest area first).
int estimateBridgeCount(const TriMesh& hull, double epsilon, std::vector<int>* seeds = nullptr);

}  // namespace acd
