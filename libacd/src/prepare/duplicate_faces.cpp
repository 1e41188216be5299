// Faces given twice: copies, double-sided faces and inner walls (acd/algo/duplicate_faces.hpp).
#include <acd/algo/duplicate_faces.hpp>

#include <acd/algo/face_order.hpp>
#include <acd/algo/union_find.hpp>

#include <algorithm>
#include <unordered_map>

namespace acd {

DuplicateOutcome resolveDuplicates(const std::vector<Face>& faces) {
  DuplicateOutcome out;
  const int nf = static_cast<int>(faces.size());
  std::vector<std::pair<Face, int>> keyed(nf);
  for (int f = 0; f < nf; ++f) {
    keyed[f] = {faces[f], f};
    std::sort(keyed[f].first.begin(), keyed[f].first.end());
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> keep(nf, 0);
  std::vector<char> doubleSided(nf, 0);  // on the kept face of a pair
  for (int i = 0; i < nf;) {
    int j = i;
    while (j < nf && keyed[j].first == keyed[i].first) ++j;
    const int first = keyed[i].second;  // lowest face number of the group
    int reverse = -1;
    for (int k = i + 1; k < j; ++k) {
      const int g = keyed[k].second;
      if (!sameCyclicOrder(faces[g], faces[first]) && reverse < 0) reverse = g;
    }
    keep[first] = 1;
    out.exactCopies += (j - i) - (reverse >= 0 ? 2 : 1);
    if (reverse >= 0) doubleSided[first] = 1;
    i = j;
  }
  if (std::count(keep.begin(), keep.end(), 1) == nf) {  // no face given twice (most meshes)
    out.faces = faces;
    return out;
  }
  // Edge uses: by single faces (c) and by double-sided pairs (p).
  const SideEdges edges = numberEdges(faces);
  std::vector<std::pair<int, int>> uses(edges.edges, {0, 0});
  auto usesOf = [&](int f, int k) -> std::pair<int, int>& { return uses[edges.edgeOfSide[3 * f + k]]; };
  for (int f = 0; f < nf; ++f)
    if (keep[f])
      for (int k = 0; k < 3; ++k) {
        auto& u = usesOf(f, k);
        (doubleSided[f] ? u.second : u.first) += 1;
      }
  UnionFind sets(nf);
  std::vector<int> firstPairOnEdge(edges.edges, -1);
  for (int f = 0; f < nf; ++f)
    if (doubleSided[f])
      for (int k = 0; k < 3; ++k) {
        if (usesOf(f, k).second < 2) continue;
        int& first = firstPairOnEdge[edges.edgeOfSide[3 * f + k]];
        if (first < 0)
          first = f;
        else
          sets.joinKeepingSmallest(first, f);
      }
  std::unordered_map<int, char> setClosesNothing;  // root -> every outer edge where the rest is closed
  for (int f = 0; f < nf; ++f)
    if (doubleSided[f]) setClosesNothing.emplace(sets.find(f), 0);
  std::unordered_map<int, int> outerEdges;
  for (int f = 0; f < nf; ++f)
    if (doubleSided[f]) {
      const int root = sets.find(f);
      for (int k = 0; k < 3; ++k) {
        const auto& u = usesOf(f, k);
        if (u.second >= 2) continue;  // inside the set
        ++outerEdges[root];
        if (u.first == 0 || u.first % 2 != 0) setClosesNothing[root] = 2;  // needed, or a free border
      }
    }
  for (int f = 0; f < nf; ++f) {
    if (!keep[f]) continue;
    if (doubleSided[f]) {
      const int root = sets.find(f);
      if (setClosesNothing[root] != 2 && outerEdges[root] > 0) {
        ++out.droppedBoth;
        continue;
      }
      ++out.keptOne;
    }
    out.faces.push_back(faces[f]);
  }
  return out;
}

}  // namespace acd
