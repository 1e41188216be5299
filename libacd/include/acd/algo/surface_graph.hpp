// Adjacency of a closed triangle mesh for walks on its surface: vertex graph (for
// Dijkstra), directed edge -> face (to know which side of a path a face is on),
// and face neighbours across edges.
#pragma once

#include <acd/mesh.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace acd {

class SurfaceGraph {
 public:
  explicit SurfaceGraph(const TriMesh& mesh);

  const TriMesh& mesh() const { return *mesh_; }
  int vertexCount() const { return static_cast<int>(start_.size()) - 1; }
  int faceCount() const { return static_cast<int>(mesh_->faces.size()); }

  /// Neighbours of v: indices [begin, end) into neighbour()/length().
  int begin(int v) const { return start_[v]; }
  int end(int v) const { return start_[v + 1]; }
  int neighbour(int slot) const { return neighbour_[slot]; }
  double length(int slot) const { return length_[slot]; }

  /// Face that has the directed edge a->b (the face on the left of a->b), or -1.
  int faceLeftOf(int a, int b) const;
  /// Slot of neighbour b in a's list, or -1 when a-b is not an edge.
  int slotOf(int a, int b) const;
  /// Face across edge k (vertices k, k+1) of face f, or -1 on a boundary.
  int faceAcross(int f, int k) const { return across_[3 * f + k]; }

 private:
  const TriMesh* mesh_;
  std::vector<int> start_, neighbour_;
  std::vector<double> length_;
  std::vector<int> leftFace_;  // per slot: the face left of v -> neighbour, or -1
  std::vector<int> across_;
};

/// Edge weight for a path search: from vertex a to neighbour b over slot `slot`.
using EdgeWeight = std::function<double(int a, int b, int slot)>;

/// Reusable Dijkstra / A* on a SurfaceGraph. Buffers are kept between calls so a
/// search touching k vertices costs O(k log k), not O(n).
class PathFinder {
 public:
  explicit PathFinder(const SurfaceGraph& graph);

  /// Shortest path s -> t as a vertex list (s first). Euclidean A* when `weight`
  /// is empty. `allowed` (optional) masks vertices the path may use; s and t always may.
  /// Returns an empty vector if t is unreachable.
  std::vector<int> path(int s, int t, const EdgeWeight& weight = {},
                        const std::vector<char>* allowed = nullptr);

  /// Multi-source Dijkstra: distance from the nearest source, and the parent to walk back. With
  /// `targets`, the search stops once all of them are settled: their distances and parent chains
  /// are final, other vertices' distances may be upper bounds.
  void flood(const std::vector<int>& sources, const EdgeWeight& weight, const std::vector<char>* allowed,
             std::vector<double>& distance, std::vector<int>& parent,
             const std::vector<int>* targets = nullptr) const;

  /// The same search in the finder's own buffers, which only the vertices it reaches touch: many
  /// searches inside small pockets of a large piece cost the pockets, not the piece. Its result
  /// is read through distance() and parent() until the next search.
  void search(const std::vector<int>& sources, const EdgeWeight& weight, const std::vector<char>* allowed,
              const std::vector<int>* targets = nullptr);
  double distance(int v) const { return dist_[v]; }
  int parent(int v) const { return parent_[v]; }
  /// The last search's path from its source to v (v alone when v was not reached).
  std::vector<int> pathTo(int v) const;

 private:
  void reset();
  const SurfaceGraph& graph_;
  std::vector<double> dist_;
  std::vector<int> parent_;
  std::vector<int> touched_;
  std::vector<char> pending_;
};

}  // namespace acd
