// Disjoint sets over 0..n-1 (union-find with path halving), for grouping faces, corners or
// vertices into connected sets.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace acd {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  /// The representative of x's set.
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  /// Joins the sets of a and b; the representative of b's set represents both.
  void join(int a, int b) { parent_[find(a)] = find(b); }

  /// Joins the sets of a and b; the smaller representative represents both, so that every
  /// representative is its set's smallest element whatever the order of the joins.
  void joinKeepingSmallest(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace acd
