#include <acd/algo/surface_graph.hpp>

#include <algorithm>
#include <limits>
#include <queue>

namespace acd {

SurfaceGraph::SurfaceGraph(const TriMesh& mesh) : mesh_(&mesh) {
  const int nv = static_cast<int>(mesh.vertices.size());
  const int nf = static_cast<int>(mesh.faces.size());
  // Each vertex's neighbours, sorted and once each: the edges bucketed by vertex (a counting
  // sort), then each vertex's few sorted on their own. The same lists as sorting every directed
  // edge as a pair, in time linear in the faces.
  std::vector<int> offset(nv + 1, 0);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) ++offset[f[k] + 1], ++offset[f[(k + 1) % 3] + 1];
  for (int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  std::vector<int> ends(offset.begin(), offset.end() - 1), all(offset[nv]);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      all[ends[a]++] = b;
      all[ends[b]++] = a;
    }
  start_.assign(nv + 1, 0);
  neighbour_.reserve(all.size() / 2);
  for (int v = 0; v < nv; ++v) {
    const auto first = all.begin() + offset[v], last = all.begin() + offset[v + 1];
    std::sort(first, last);
    neighbour_.insert(neighbour_.end(), first, std::unique(first, last));
    start_[v + 1] = static_cast<int>(neighbour_.size());
  }
  length_.resize(neighbour_.size());
  for (int v = 0; v < nv; ++v)
    for (int slot = start_[v]; slot < start_[v + 1]; ++slot)
      length_[slot] = (mesh.vertices[v] - mesh.vertices[neighbour_[slot]]).norm();
  // Neighbour lists are sorted, so a directed edge's slot is found by bisection. On a repeated
  // directed edge (a non-manifold input) the later face is kept.
  leftFace_.assign(neighbour_.size(), -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      leftFace_[slotOf(a, b)] = f;
    }
  across_.assign(3 * nf, -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) across_[3 * f + k] = faceLeftOf(mesh.faces[f][(k + 1) % 3], mesh.faces[f][k]);
}

int SurfaceGraph::slotOf(int a, int b) const {
  const auto first = neighbour_.begin() + start_[a], last = neighbour_.begin() + start_[a + 1];
  const auto it = std::lower_bound(first, last, b);
  return it != last && *it == b ? static_cast<int>(it - neighbour_.begin()) : -1;
}

int SurfaceGraph::faceLeftOf(int a, int b) const {
  const int slot = slotOf(a, b);
  return slot < 0 ? -1 : leftFace_[slot];
}

PathFinder::PathFinder(const SurfaceGraph& graph)
    : graph_(graph),
      dist_(graph.vertexCount(), std::numeric_limits<double>::infinity()),
      parent_(graph.vertexCount(), -1) {}

void PathFinder::reset() {
  for (int v : touched_) {
    dist_[v] = std::numeric_limits<double>::infinity();
    parent_[v] = -1;
  }
  touched_.clear();
}

std::vector<int> PathFinder::path(int s, int t, const EdgeWeight& weight, const std::vector<char>* allowed) {
  const auto& P = graph_.mesh().vertices;
  const bool astar = !weight;
  auto heuristic = [&](int v) { return astar ? (P[v] - P[t]).norm() : 0.0; };
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  reset();
  dist_[s] = 0.0;
  touched_.push_back(s);
  open.emplace(heuristic(s), s);
  bool found = false;
  while (!open.empty()) {
    const auto [key, v] = open.top();
    open.pop();
    if (v == t) {
      found = true;
      break;
    }
    if (key - heuristic(v) > dist_[v] * (1 + 1e-12) + 1e-300) continue;  // stale entry
    for (int slot = graph_.begin(v); slot < graph_.end(v); ++slot) {
      const int w = graph_.neighbour(slot);
      if (allowed && w != t && !(*allowed)[w]) continue;
      const double d = dist_[v] + (astar ? graph_.length(slot) : weight(v, w, slot));
      if (d < dist_[w]) {
        if (dist_[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
        dist_[w] = d;
        parent_[w] = v;
        open.emplace(d + heuristic(w), w);
      }
    }
  }
  std::vector<int> result;
  if (!found) return result;
  for (int v = t; v != -1; v = parent_[v]) result.push_back(v);
  std::reverse(result.begin(), result.end());
  return result;
}

void PathFinder::flood(const std::vector<int>& sources, const EdgeWeight& weight, const std::vector<char>* allowed,
                       std::vector<double>& distance, std::vector<int>& parent, const std::vector<int>* targets) const {
  PathFinder own(graph_);  // fresh buffers: a vertex the search does not reach stays at infinity
  own.search(sources, weight, allowed, targets);
  distance = std::move(own.dist_);
  parent = std::move(own.parent_);
}

void PathFinder::search(const std::vector<int>& sources, const EdgeWeight& weight, const std::vector<char>* allowed,
                        const std::vector<int>* targets) {
  reset();
  int unsettled = 0;
  if (targets) {
    if (pending_.empty()) pending_.assign(graph_.vertexCount(), 0);
    for (int t : *targets)
      if (!pending_[t]) pending_[t] = 1, ++unsettled;
  }
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  for (int s : sources) {
    if (dist_[s] == std::numeric_limits<double>::infinity()) touched_.push_back(s);
    dist_[s] = 0.0;
    open.emplace(0.0, s);
  }
  while (!open.empty()) {
    const auto [d, v] = open.top();
    open.pop();
    if (d > dist_[v]) continue;
    if (targets && pending_[v]) {
      pending_[v] = 0;
      if (--unsettled == 0) break;
    }
    for (int slot = graph_.begin(v); slot < graph_.end(v); ++slot) {
      const int w = graph_.neighbour(slot);
      if (allowed && !(*allowed)[w]) continue;
      const double nd = d + (weight ? weight(v, w, slot) : graph_.length(slot));
      if (nd < dist_[w]) {
        if (dist_[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
        dist_[w] = nd;
        parent_[w] = v;
        open.emplace(nd, w);
      }
    }
  }
  if (targets)
    for (int t : *targets) pending_[t] = 0;
}

std::vector<int> PathFinder::pathTo(int v) const {
  std::vector<int> path;
  for (; v != -1; v = parent_[v]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace acd
