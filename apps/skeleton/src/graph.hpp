// Undirected simple graphs with 3D node positions: the skeletons compared by graph edit distance.
#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace skeleton {

using Vec3 = Eigen::Vector3d;

/// What a skeleton node stands for; the graph edit distance ignores it (unlabelled graphs).
enum class NodeKind { Component, Cut, Curve };

const char* toString(NodeKind kind);

struct Node {
  Vec3 position = Vec3::Zero();
  NodeKind kind = NodeKind::Curve;
  int source = -1;  // component index for Component nodes, -1 otherwise
};

/// Simple undirected graph: no self-loops, no parallel edges; edges stored with first < second.
struct Graph {
  std::vector<Node> nodes;
  std::vector<std::pair<int, int>> edges;

  int nodeCount() const { return static_cast<int>(nodes.size()); }
  int edgeCount() const { return static_cast<int>(edges.size()); }
  int addNode(const Vec3& position, NodeKind kind = NodeKind::Curve, int source = -1);
  /// Adds {a, b} unless a == b or the edge exists; returns whether it was added.
  bool addEdge(int a, int b);
};

/// Graph from a node count and an edge list (positions zero); loops and repeats are dropped.
Graph makeGraph(int nodes, const std::vector<std::pair<int, int>>& edges);

/// Degrees of all nodes.
std::vector<int> degrees(const Graph& g);

/// Dense adjacency matrix (row-major, n*n, 0/1).
std::vector<char> adjacency(const Graph& g);

/// Number of connected components.
int connectedComponents(const Graph& g);

/// Contracts degree-2 nodes (the paper's D2 ignores them: inserting or deleting one does not
/// change the graph's topology). A degree-2 node v with neighbours a, b is removed and its two
/// edges replaced by the edge {a, b}, repeatedly, in index order, as long as a and b are not
/// already adjacent: the result stays a simple graph, so a chain between two branch nodes
/// becomes one edge, a second parallel chain between the same pair keeps one node, a cycle
/// through a single branch node keeps two, and a cycle with no branch node becomes a triangle.
/// The result is unique up to isomorphism. Positions and kinds of kept nodes are kept.
Graph contractDegreeTwo(const Graph& g);

/// The contraction with its correspondence to the input.
struct Contraction {
  Graph graph;                          // as contractDegreeTwo returns it
  std::vector<int> kept;                // node of `graph` -> node of the input
  std::vector<std::vector<int>> chains; // per edge of `graph` (same order): the removed input nodes along it, from edge.first to edge.second
};
Contraction contractWithChains(const Graph& g);

}  // namespace skeleton
