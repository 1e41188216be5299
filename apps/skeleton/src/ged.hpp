// Graph edit distance between unlabelled undirected graphs.
//
// Cost model: inserting or deleting a node costs 1, inserting or deleting an edge costs 1,
// substituting a node for a node (or an edge for an edge) costs 0: node positions and kinds
// are ignored. A node deleted with its edges pays for each edge as well. This is networkx's
// `graph_edit_distance` with its default costs.
//
// Exact: depth-first branch and bound over node maps, nodes of the first graph taken in a
// connected order, with the Riesen-Bunke assignment bound (edges to already mapped nodes
// counted exactly, edges among unmapped nodes by half the degree difference) as an admissible
// lower bound; the bipartite answer below seeds the upper bound.
// Approximate: Riesen & Bunke, "Approximate graph edit distance computation by means of
// bipartite graph matching" (Image and Vision Computing 27, 2009): one assignment problem
// solved by the Hungarian algorithm gives a node map, and the cost of the edit path it
// induces is an upper bound on the distance. That path is then improved by local search
// (moving one node's image to a free node, or swapping the images of two nodes, while that
// lowers the cost) and iterated local search from random swaps; every path it visits is a
// valid edit path, so the result is still an upper bound. The same
// assignment with nothing mapped is a lower bound, reported beside it.
#pragma once

#include "graph.hpp"

#include <string>
#include <vector>

namespace skeleton {

struct GedOptions {
  int exactMaxNodes = 12;             // exact when both graphs have at most this many nodes
  long long maxExpansions = 20000000; // search budget of the exact method; beyond it the best path found is reported
  long long mipMaxColumns = 3000;     // larger graphs whose program (ged_mip.hpp) has at most this many variables:
                                      // n1 n2 + m1 m2 (the table's contracted CGAL skeletons: at most 2665)
  int mipMaxBranchNodes = 1000;       // its search budget (the table's CGAL skeletons need at most 191 nodes
  int mipMaxIterations = 100000;      // and 50 000 simplex iterations)
};

struct GedResult {
  int distance = 0;         // cost of the best edit path found (the distance when `exact`)
  int lowerBound = 0;       // proven lower bound (== distance when `exact`)
  bool exact = false;       // distance proven optimal (exact search finished, or the bounds met)
  std::string method;       // "exact" (branch and bound), "mip" (binary program) or "bipartite"
  int assignmentCost = 0;   // bipartite: cost of the Riesen-Bunke path before local search
  std::vector<int> mapping; // node of the first graph -> node of the second, -1 = deleted
  long long expansions = 0; // search nodes expanded by the exact method
  double seconds = 0.0;
};

/// Cost of the edit path induced by a node map (each first-graph node to a distinct
/// second-graph node or -1); second-graph nodes nobody maps to are inserted.
int editPathCost(const Graph& a, const Graph& b, const std::vector<int>& mapping);

/// Exact distance (branch and bound); gives up after `maxExpansions` expanded search nodes,
/// then `exact` is false and `distance` is the best path found.
GedResult exactGed(const Graph& a, const Graph& b, long long maxExpansions = 20000000);

/// Riesen-Bunke bipartite upper bound improved by local search, with the assignment lower bound.
GedResult bipartiteGed(const Graph& a, const Graph& b);

/// Local search on a node map (see above), then `kicks` rounds of iterated local search (a few
/// random swaps, descend again, keep unless worse; fixed seed). Returns the cost of the
/// improved map, never worse than the given one.
int improveMapping(const Graph& a, const Graph& b, std::vector<int>& mapping, int kicks = 300);

/// Exact when both graphs are small enough (options.exactMaxNodes); else the bipartite path,
/// proven or improved by the binary program when it has at most options.mipMaxColumns variables.
GedResult graphEditDistance(const Graph& a, const Graph& b, const GedOptions& options = {});

}  // namespace skeleton
