#include "parts.hpp"

#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "acd_skeleton.hpp"
#include "part_voxels.hpp"

namespace skeleton {

namespace {

/// Cuts between two parts, summed: area, area-weighted centre, area-weighted normal out of the
/// first of the pair.
struct Contact {
  double area = 0.0;
  Vec3 moment = Vec3::Zero(), normal = Vec3::Zero();
};

/// Extent of the components `members` along `n`.
double extentAlong(const std::vector<acd::TriMesh>& components, const std::vector<int>& members, const Vec3& n) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int c : members)
    for (const Vec3& v : components[c].vertices) {
      const double t = n.dot(v);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  return hi > lo ? hi - lo : 0.0;
}

constexpr int kNoName = std::numeric_limits<int>::max();  // after every pair of names

/// Components joined into parts step by step. Parts are named by their lowest component; ties go
/// to the lower pair of names (components come in canonical order).
class Merger {
 public:
  Merger(const std::vector<acd::TriMesh>& components, const std::vector<Cut>& cuts, const std::vector<double>& volume)
      : components_(components), cuts_(cuts), sets_(static_cast<int>(components.size())), volume_(volume) {
    for (int i = 0; i < static_cast<int>(components.size()); ++i) members_.push_back({i});
  }

  /// Merges the most tube-like contact while its section ratio is at least `tubeRatio`.
  void mergeTubes(double tubeRatio) {
    for (;;) {
      double best = -1.0;
      std::pair<int, int> bestPair{-1, -1}, bestKey{kNoName, kNoName};
      for (const auto& [pair, k] : contacts()) {
        if (!(k.area > 0) || !(k.normal.norm() > 0)) continue;
        const Vec3 axis = k.normal.normalized();
        double widest = 0.0;
        for (int p : {pair.first, pair.second}) {
          const double extent = extentAlong(components_, members_[p], axis);
          if (extent > 0) widest = std::max(widest, volume_[p] / extent);
        }
        if (!(widest > 0)) continue;
        const double ratio = k.area / widest;
        const std::pair<int, int> key = nameOf(pair);
        if (ratio > best || (ratio == best && key < bestKey)) best = ratio, bestPair = pair, bestKey = key;
      }
      if (best < tubeRatio) return;
      join(bestPair.first, bestPair.second);
    }
  }

  /// Stubs: a part that is no longer along its largest contact's normal than the contact is wide,
  /// and smaller than the part on the other side, is a wedge filling the crease where two parts
  /// meet or a bump on one; it goes into the part it shares that contact with, the flattest first.
  void mergeStubs() {
    for (;;) {
      double flattest = kStubElongation;
      std::pair<int, int> bestPair{-1, -1}, bestKey{kNoName, kNoName};
      std::map<int, std::pair<double, std::pair<int, int>>> largest;  // part -> (area, contact)
      const auto between = contacts();
      for (const auto& [pair, k] : between)
        for (int p : {pair.first, pair.second}) {
          auto& l = largest[p];
          if (k.area > l.first) l = {k.area, pair};
        }
      for (const auto& [p, l] : largest) {
        const Contact& k = between.at(l.second);
        if (!(k.area > 0) || !(k.normal.norm() > 0)) continue;
        const double extent = extentAlong(components_, members_[p], k.normal.normalized());
        const int other = l.second.first == p ? l.second.second : l.second.first;
        if (!(extent > 0) || !(volume_[p] < volume_[other])) continue;
        const double elongation = extent / std::sqrt(k.area);
        const std::pair<int, int> key = nameOf(l.second);
        if (elongation < flattest || (elongation == flattest && key < bestKey))
          flattest = elongation, bestPair = l.second, bestKey = key;
      }
      if (bestPair.first < 0) return;
      join(bestPair.first, bestPair.second);
    }
  }

  /// Specks (leastPartShare): each part of less than `leastVolume` goes into the neighbour it
  /// shares the most area with, the smallest first.
  void mergeSpecks(double leastVolume) {
    for (;;) {
      const auto between = contacts();
      int smallest = -1;
      for (const auto& [pair, k] : between)
        for (int p : {pair.first, pair.second})
          if (volume_[p] < leastVolume &&
              (smallest < 0 || volume_[p] < volume_[smallest] ||
               (volume_[p] == volume_[smallest] && members_[p][0] < members_[smallest][0])))
            smallest = p;
      if (smallest < 0) return;
      int into = -1;
      double most = -1.0;
      for (const auto& [pair, k] : between) {
        if (pair.first != smallest && pair.second != smallest) continue;
        const int other = pair.first == smallest ? pair.second : pair.first;
        if (into < 0 || k.area > most || (k.area == most && members_[other][0] < members_[into][0]))
          most = k.area, into = other;
      }
      join(smallest, into);
    }
  }

  int merges() const { return merges_; }
  int root(int component) { return sets_.find(component); }
  const std::vector<int>& members(int root) const { return members_[root]; }

 private:
  /// Contacts between parts (by union-find root), summed over the cuts between them.
  std::map<std::pair<int, int>, Contact> contacts() {
    std::map<std::pair<int, int>, Contact> between;
    for (const Cut& c : cuts_) {
      const int pa = sets_.find(c.a), pb = sets_.find(c.b);
      if (pa == pb) continue;
      const std::pair<int, int> key = std::minmax(pa, pb);
      Contact& k = between[key];
      k.area += c.area;
      k.moment += c.area * c.centre;
      k.normal += (pa == key.first ? 1.0 : -1.0) * c.area * c.normal;  // out of key.first, c.normal out of c.a
    }
    return between;
  }

  std::pair<int, int> nameOf(const std::pair<int, int>& roots) const {
    return std::minmax(members_[roots.first][0], members_[roots.second][0]);
  }

  void join(int a, int b) {
    const int keep = sets_.find(a), gone = sets_.find(b);
    sets_.join(keep, gone);
    const int root = sets_.find(keep), other = root == keep ? gone : keep;
    members_[root].insert(members_[root].end(), members_[other].begin(), members_[other].end());
    std::sort(members_[root].begin(), members_[root].end());
    members_[other].clear();
    volume_[root] += volume_[other];
    ++merges_;
  }

  const std::vector<acd::TriMesh>& components_;
  const std::vector<Cut>& cuts_;
  acd::UnionFind sets_;
  std::vector<std::vector<int>> members_;
  std::vector<double> volume_;  // per root: the part's volume
  int merges_ = 0;
};

/// The adjacencies of the parts a skeleton keeps: a maximum spanning forest by shared area; with
/// `handleCycles`, also (largest first, ties: lower pair of parts) the others that a loop of the
/// solid passes through, no more than its genus. Where the solid has handles, the grid that shows
/// them all counts each part's own and the adjacencies loops pass through.
void keepJoints(const std::vector<acd::TriMesh>& components, const std::vector<Cut>& cuts, int genus,
                bool handleCycles, Parts& parts) {
  std::map<std::pair<int, int>, Contact> between;
  for (const Cut& c : cuts) {
    const int pa = parts.partOf[c.a], pb = parts.partOf[c.b];
    if (pa == pb) continue;
    Contact& k = between[std::minmax(pa, pb)];
    k.area += c.area;
    k.moment += c.area * c.centre;
  }
  std::vector<Joint> adjacent;
  for (const auto& [pair, k] : between)
    adjacent.push_back({pair.first, pair.second, k.area, k.area > 0 ? Vec3(k.moment / k.area) : Vec3::Zero()});
  std::stable_sort(adjacent.begin(), adjacent.end(), [](const Joint& x, const Joint& y) { return x.area > y.area; });
  acd::UnionFind forest(static_cast<int>(parts.members.size()));
  std::vector<char> taken(adjacent.size(), 0);
  for (std::size_t j = 0; j < adjacent.size(); ++j) {
    const int ra = forest.find(adjacent[j].a), rb = forest.find(adjacent[j].b);
    if (ra != rb) forest.join(ra, rb), taken[j] = 1;
  }
  if (genus > 0)
    for (int cells : kPartGridSizes) {
      const PartVoxels grid(components, parts.partOf, cells);
      if (grid.loops() != genus) continue;
      parts.loopGrid = cells;
      for (int p = 0; p < static_cast<int>(parts.members.size()); ++p) parts.handles.push_back(grid.loops(p));
      for (std::size_t j = 0; j < adjacent.size(); ++j) {
        acd::UnionFind others(static_cast<int>(parts.members.size()));
        for (std::size_t i = 0; i < adjacent.size(); ++i)
          if (i != j) others.join(others.find(adjacent[i].a), others.find(adjacent[i].b));
        const bool joined = others.find(adjacent[j].a) == others.find(adjacent[j].b);
        if (grid.loopsThrough(adjacent[j].a, adjacent[j].b, joined) > 0) parts.loopJoints.push_back(adjacent[j]);
      }
      break;
    }
  if (handleCycles) {
    int cycles = 0;
    const auto carriesLoop = [&parts](const Joint& j) {
      return std::any_of(parts.loopJoints.begin(), parts.loopJoints.end(),
                         [&j](const Joint& l) { return l.a == j.a && l.b == j.b; });
    };
    // No grid shows all the solid's handles (some thinner than its cubes): the largest stand in.
    for (std::size_t j = 0; j < adjacent.size() && cycles < genus; ++j)
      if (!taken[j] && (parts.loopGrid == 0 || carriesLoop(adjacent[j]))) taken[j] = 1, ++cycles;
  }
  for (std::size_t j = 0; j < adjacent.size(); ++j)
    if (taken[j])
      parts.joints.push_back(adjacent[j]);
    else
      ++parts.droppedAdjacencies;
  std::sort(parts.joints.begin(), parts.joints.end(),
            [](const Joint& x, const Joint& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
}

}  // namespace

Parts groupIntoParts(const std::vector<acd::TriMesh>& components, int genus, bool handleCycles, double tubeRatio,
                     double leastVolumeShare) {
  const int n = static_cast<int>(components.size());
  std::vector<double> volume(n);
  std::vector<Vec3> centroid(n);
  for (int i = 0; i < n; ++i) {
    volume[i] = std::abs(acd::signedVolume(components[i]));
    centroid[i] = solidCentroid(components[i]);
  }
  const std::vector<Cut> cuts = findCuts(components);
  Merger merger(components, cuts, volume);
  merger.mergeTubes(tubeRatio);
  merger.mergeStubs();
  merger.mergeSpecks(leastVolumeShare * std::accumulate(volume.begin(), volume.end(), 0.0));

  Parts parts;
  parts.merges = merger.merges();
  parts.partOf.assign(n, -1);
  std::vector<int> partOfRoot(n, -1);
  for (int i = 0; i < n; ++i) {  // parts in the order of their first component
    const int root = merger.root(i);
    if (partOfRoot[root] < 0) {
      partOfRoot[root] = static_cast<int>(parts.members.size());
      parts.members.push_back(merger.members(root));
      double v = 0.0;
      Vec3 moment = Vec3::Zero();
      for (int c : merger.members(root)) v += volume[c], moment += volume[c] * centroid[c];
      parts.volume.push_back(v);
      parts.centroid.push_back(v > 0 ? Vec3(moment / v) : centroid[i]);
    }
    parts.partOf[i] = partOfRoot[root];
  }
  keepJoints(components, cuts, genus, handleCycles, parts);
  return parts;
}

Graph skeletonFromParts(const Parts& parts) {
  Graph g;
  for (int p = 0; p < static_cast<int>(parts.members.size()); ++p) g.addNode(parts.centroid[p], NodeKind::Component, p);
  for (const Joint& j : parts.joints) {
    const int node = g.addNode(j.centre, NodeKind::Cut);
    g.addEdge(j.a, node);
    g.addEdge(j.b, node);
  }
  return g;
}

int genusOf(const acd::TriMesh& mesh) {
  const int nv = static_cast<int>(mesh.vertices.size());
  acd::UnionFind shells(nv);
  std::set<std::pair<int, int>> edges;
  for (const acd::Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      edges.insert(std::minmax(f[k], f[(k + 1) % 3]));
      shells.join(shells.find(f[k]), shells.find(f[(k + 1) % 3]));
    }
  // Euler characteristic per shell: V - E + F over the vertices the faces use.
  std::map<int, long long> chi;
  std::vector<char> used(nv, 0);
  for (const acd::Face& f : mesh.faces) {
    ++chi[shells.find(f[0])];
    for (int v : f) used[v] = 1;
  }
  for (int v = 0; v < nv; ++v)
    if (used[v]) ++chi[shells.find(v)];
  for (const auto& [a, b] : edges) --chi[shells.find(a)];
  int genus = 0;
  for (const auto& [root, x] : chi) genus += static_cast<int>(std::max(0LL, (2 - x) / 2));
  return genus;
}

}  // namespace skeleton
