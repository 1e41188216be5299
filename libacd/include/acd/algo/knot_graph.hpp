// The knot graph G_K (Lien & Amato 2007, Section 4.2.4): knots are its nodes, pocket cuts
// between matched knots (Observation 4.2) and links along shared pocket boundaries its edges.
// The global cut is the minimum-weight cycle of G_K through the pocket cut nearest the notch.
#pragma once

#include <acd/algo/concavity.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/surface_graph.hpp>

#include <vector>

namespace acd {

struct KnotGraph {
  struct Edge {
    int a = -1, b = -1;        // node indices
    double weight = 0.0;       // Eq. 4 summed along the path
    int pocket = -1;           // pocket the cut runs in; -1 for a link along a boundary
    std::vector<int> path;     // mesh vertices from a's knot to b's knot
  };
  std::vector<Knot> nodes;
  std::vector<Edge> edges;
};

/// Knots of every pocket, pocket cuts between the matched knots of every pair of boundaries
/// of each pocket, and links joining the knots two pockets found on their shared boundary.
KnotGraph buildKnotGraph(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map, double delta,
                         const std::vector<double>* slotCurvature = nullptr);

/// Minimum-weight cycle of G_K through the root pocket cut (the cut of the notch's pocket whose
/// path holds the notch, or passes nearest to it). Empty when the notch's pocket has no cut or
/// no cycle closes.
GlobalCut knotGraphCycle(const TriMesh& mesh, const ConcavityMap& map, const KnotGraph& kg);

}  // namespace acd
