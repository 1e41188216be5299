#include "correspondence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "assignment.hpp"

namespace skeleton {

namespace {

std::vector<int> hullOfVertices(const acd::TriMesh& mesh, const std::vector<acd::TriMesh>& hulls) {
  struct Facet {
    Vec3 n;
    double d;
  };
  std::vector<std::vector<Facet>> planes(hulls.size());
  for (std::size_t h = 0; h < hulls.size(); ++h)
    for (const acd::Face& f : hulls[h].faces) {
      const Vec3 &p = hulls[h].vertices[f[0]], &q = hulls[h].vertices[f[1]], &r = hulls[h].vertices[f[2]];
      const Vec3 n = (q - p).cross(r - p);
      if (n.norm() > 0) planes[h].push_back({n.normalized(), n.normalized().dot(p)});
    }
  std::vector<int> owner(mesh.vertices.size(), -1);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < planes.size(); ++h) {
      double depth = -std::numeric_limits<double>::infinity();
      for (const Facet& f : planes[h]) depth = std::max(depth, f.n.dot(mesh.vertices[v]) - f.d);
      if (!planes[h].empty() && depth < best) best = depth, owner[v] = static_cast<int>(h);
    }
  }
  return owner;
}

}  // namespace

std::vector<int> componentOfVertices(const acd::TriMesh& mesh, const std::vector<acd::TriMesh>& components,
                                     const std::vector<acd::TriMesh>& hulls) {
  const double diagonal = acd::boundingBox(mesh).size().norm();
  const double reach = 1e-6 * (diagonal > 0 ? diagonal : 1.0);
  // A grid of cells `reach` wide: a vertex's match lies in its own cell or a neighbouring one.
  using Cell = std::array<long long, 3>;
  const auto cellOf = [&](const Vec3& p) {
    return Cell{static_cast<long long>(std::floor(p.x() / reach)), static_cast<long long>(std::floor(p.y() / reach)),
                static_cast<long long>(std::floor(p.z() / reach))};
  };
  std::map<Cell, std::vector<std::pair<Vec3, int>>> grid;
  for (int c = 0; c < static_cast<int>(components.size()); ++c)
    for (const Vec3& v : components[c].vertices) grid[cellOf(v)].push_back({v, c});
  std::vector<int> owner = hullOfVertices(mesh, hulls);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const Cell home = cellOf(p);
    int best = -1;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({home[0] + dx, home[1] + dy, home[2] + dz});
          if (it == grid.end()) continue;
          for (const auto& [v, c] : it->second)
            if ((v - p).norm() <= reach && (best < 0 || c < best)) best = c;
        }
    if (best >= 0) owner[i] = best;
  }
  return owner;
}

std::vector<int> correspondenceMap(const Graph& a, const std::vector<int>& vertexPartA, const Graph& b,
                                   const std::vector<int>& vertexPartB) {
  // Part nodes are the Component nodes; `source` is the part's index.
  std::map<int, int> nodeOfPartA, nodeOfPartB;
  for (int i = 0; i < a.nodeCount(); ++i)
    if (a.nodes[i].kind == NodeKind::Component) nodeOfPartA[a.nodes[i].source] = i;
  for (int i = 0; i < b.nodeCount(); ++i)
    if (b.nodes[i].kind == NodeKind::Component) nodeOfPartB[b.nodes[i].source] = i;
  const int na = static_cast<int>(nodeOfPartA.size()), nb = static_cast<int>(nodeOfPartB.size());
  const int n = std::max(na, nb);
  std::vector<int> rowOf(a.nodeCount(), -1), colOf(b.nodeCount(), -1), nodeOfRow, nodeOfCol;
  for (const auto& [part, node] : nodeOfPartA)
    rowOf[node] = static_cast<int>(nodeOfRow.size()), nodeOfRow.push_back(node);
  for (const auto& [part, node] : nodeOfPartB)
    colOf[node] = static_cast<int>(nodeOfCol.size()), nodeOfCol.push_back(node);
  std::vector<double> shared(static_cast<std::size_t>(n) * n, 0.0);
  const std::size_t vertices = std::min(vertexPartA.size(), vertexPartB.size());
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto ia = nodeOfPartA.find(vertexPartA[v]), ib = nodeOfPartB.find(vertexPartB[v]);
    if (ia == nodeOfPartA.end() || ib == nodeOfPartB.end()) continue;
    shared[static_cast<std::size_t>(rowOf[ia->second]) * n + colOf[ib->second]] += 1.0;
  }
  std::vector<double> cost(shared.size());
  for (std::size_t k = 0; k < shared.size(); ++k) cost[k] = -shared[k];
  const std::vector<int> column = solveAssignment(cost, n);
  std::vector<int> map(a.nodeCount(), -1);
  for (int r = 0; r < na; ++r) {
    const int c = column[r];
    if (c < nb && shared[static_cast<std::size_t>(r) * n + c] > 0) map[nodeOfRow[r]] = nodeOfCol[c];
  }
  // Cut nodes follow their two parts.
  std::vector<std::vector<int>> nbrA(a.nodeCount()), nbrB(b.nodeCount());
  for (const auto& [x, y] : a.edges) nbrA[x].push_back(y), nbrA[y].push_back(x);
  for (const auto& [x, y] : b.edges) nbrB[x].push_back(y), nbrB[y].push_back(x);
  std::map<std::pair<int, int>, int> cutOfB;
  for (int i = 0; i < b.nodeCount(); ++i)
    if (b.nodes[i].kind == NodeKind::Cut && nbrB[i].size() == 2) cutOfB[std::minmax(nbrB[i][0], nbrB[i][1])] = i;
  std::vector<char> used(b.nodeCount(), 0);
  for (int i = 0; i < a.nodeCount(); ++i)
    if (map[i] >= 0) used[map[i]] = 1;
  for (int i = 0; i < a.nodeCount(); ++i) {
    if (a.nodes[i].kind != NodeKind::Cut || nbrA[i].size() != 2) continue;
    const int x = map[nbrA[i][0]], y = map[nbrA[i][1]];
    if (x < 0 || y < 0) continue;
    const auto it = cutOfB.find(std::minmax(x, y));
    if (it != cutOfB.end() && !used[it->second]) map[i] = it->second, used[it->second] = 1;
  }
  return map;
}

std::vector<int> contractedMap(const Contraction& a, const Contraction& b, const std::vector<int>& map, int nodesOfB) {
  std::vector<int> keptIndexOfB(nodesOfB, -1);
  for (std::size_t k = 0; k < b.kept.size(); ++k) keptIndexOfB[b.kept[k]] = static_cast<int>(k);
  std::vector<int> out(a.kept.size(), -1);
  for (std::size_t k = 0; k < a.kept.size(); ++k) {
    const int image = map[a.kept[k]];
    if (image >= 0) out[k] = keptIndexOfB[image];
  }
  return out;
}

}  // namespace skeleton
