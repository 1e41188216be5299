// Feature grouping (Lien & Amato 2007, Section 4.2): knots on pocket boundaries,
// pocket cuts between knots, and a global cut grown from the most concave pocket
// cut through neighbouring pockets until its two ends meet.
#pragma once

#include <acd/algo/concavity.hpp>
#include <acd/algo/surface_graph.hpp>

#include <vector>

namespace acd {

struct FeatureOptions {
  double delta = 0.0025;   // Douglas-Peucker tolerance in concavity space (normalised units)
  int maxPockets = 12;     // pockets a global cut may cross before it is closed by force
  bool matchKnots = true;  // legs end only at knots matched to the entry knot (Observation 4.2)
  bool notchAsEnd = true;  // a notch on a pocket boundary is itself one end of the root pocket cut
  /// slotCurvatures(mesh, graph), when the caller shares one between calls (else made per call).
  const std::vector<double>* slotCurvature = nullptr;
};

/// A knot: a mesh vertex on a pocket boundary, with the pocket it was found for.
struct Knot {
  int vertex = -1;
  int pocket = -1;         // bridge index whose pocket the knot bounds
  int projection = -1;     // index into ConcavityMap::projections
  double concavity = 0.0;  // with respect to `pocket`'s bridge
  int along = -1;          // index of the vertex in the projection's path
};

/// Observation 4.2: minimum-weight non-crossing bipartite matching between the knots of two
/// boundaries of one pocket. Rows and columns are both listed in the order met walking once
/// around the pocket, so two pairs (i, j), (i', j') with i < i' do not cross iff j > j'.
/// cost[i][j] = infinity forbids a pair. Maximises the number of pairs, then minimises the
/// total cost. Returns (row, column) pairs with ascending rows.
std::vector<std::pair<int, int>> nonCrossingMatching(const std::vector<std::vector<double>>& cost);

struct GlobalCut {
  std::vector<int> vertices;    // mesh vertices along the cut (a chain or a cycle)
  std::vector<double> weight;   // concavity of each vertex in the pocket it was reached through
  std::vector<Knot> knots;      // knots the cut passes through
  std::vector<int> pockets;     // pockets crossed, in order of growth
  bool closed = false;          // the two growing ends met
  bool cupShaped = false;       // the root pocket had no usable knots (Figure 13)
};

/// Knots of every boundary of pocket `bridge`.
std::vector<Knot> pocketKnots(const TriMesh& mesh, const ConcavityMap& map, int bridge, double delta);

/// Curvature term of cutEdgeWeight (Eq. 4) for every adjacency slot of `graph` (concave dihedral angle,
/// 0 for convex edges), computed once so that repeated floods do not recompute face normals.
std::vector<double> slotCurvatures(const TriMesh& mesh, const SurfaceGraph& graph);

/// Edge weight for pocket cuts, Eq. 4 per edge: length / (concavity * curvature), each term
/// offset so flat, convex or zero-concavity edges stay usable but expensive. Curvature is the
/// edge's concave dihedral angle (slotCurvatures; see docs/ALGORITHM.md).
inline double cutEdgeWeight(double concavityA, double concavityB, double curvature, double length) {
  return length / ((0.5 * (concavityA + concavityB) + 0.01) * (curvature + 0.1));
}

/// The global cut through the component's notch.
GlobalCut findGlobalCut(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map,
                        const FeatureOptions& options);

}  // namespace acd
