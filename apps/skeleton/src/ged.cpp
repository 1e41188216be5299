#include "ged.hpp"

#include <acd/algo/stopwatch.hpp>

#include "assignment.hpp"
#include "ged_mip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <tuple>

namespace skeleton {

namespace {

constexpr double kForbidden = 1e9;  // assignment cells that stand for no edit operation

/// Node maps from graph a to graph b, built one node of a at a time. Costs are kept doubled
/// inside the assignment bound so that half-edges stay integers.
class EditSearch {
 public:
  EditSearch(const Graph& a, const Graph& b)
      : n1_(a.nodeCount()), n2_(b.nodeCount()), adj1_(adjacency(a)), adj2_(adjacency(b)),
        image_(n1_, kUnmapped), preimage_(n2_, -1) {
    order_ = connectedOrder(a);
  }

  /// Lower bound on the cost still to pay once the first `k` nodes of the order are mapped
  /// (exact when k == n1: then only insertions are left). When asked, `assignment` gets the
  /// node map the assignment proposes for the unmapped nodes (-1: delete).
  int boundAfter(int k, std::vector<int>* assignment = nullptr) const {
    std::vector<int> rest1(order_.begin() + k, order_.end()), rest2;
    for (int v = 0; v < n2_; ++v)
      if (preimage_[v] < 0) rest2.push_back(v);
    const int r1 = static_cast<int>(rest1.size()), r2 = static_cast<int>(rest2.size()), m = r1 + r2;
    if (m == 0) return 0;
    std::vector<double> cost(static_cast<std::size_t>(m) * m, kForbidden);
    std::vector<int> degree2(r2, 0), toUsed2(r2, 0);
    for (int j = 0; j < r2; ++j) {
      const int v = rest2[j];
      for (int w = 0; w < n2_; ++w) {
        if (!edge2(v, w)) continue;
        if (preimage_[w] < 0) ++degree2[j];
        else ++toUsed2[j];
      }
    }
    for (int i = 0; i < r1; ++i) {
      const int u = rest1[i];
      int degree1 = 0, toDone1 = 0;
      for (int w = 0; w < n1_; ++w) {
        if (!edge1(u, w)) continue;
        if (image_[w] == kUnmapped) ++degree1;
        else ++toDone1;
      }
      for (int j = 0; j < r2; ++j) {
        const int v = rest2[j];
        int cross = 0;  // edges to mapped nodes that would disagree: paid exactly
        for (int p = 0; p < n1_; ++p) {
          if (image_[p] == kUnmapped) continue;
          const bool e2 = image_[p] >= 0 && edge2(v, image_[p]);
          cross += edge1(u, p) != e2;
        }
        cost[i * m + j] = 2.0 * cross + std::abs(degree1 - degree2[j]);
      }
      cost[i * m + r2 + i] = 2.0 * (1 + toDone1) + degree1;  // delete u
    }
    for (int j = 0; j < r2; ++j) {
      cost[(r1 + j) * m + j] = 2.0 * (1 + toUsed2[j]) + degree2[j];  // insert rest2[j]
      for (int i = 0; i < r1; ++i) cost[(r1 + j) * m + r2 + i] = 0.0;
    }
    double total = 0.0;
    const std::vector<int> columns = solveAssignment(cost, m, &total);
    if (assignment) {
      assignment->assign(n1_, -1);  // indexed by node of a; only the unmapped ones are set
      for (int i = 0; i < r1; ++i)
        if (columns[i] < r2) (*assignment)[rest1[i]] = rest2[columns[i]];
    }
    return static_cast<int>(std::ceil(total / 2.0 - 1e-9));
  }

  /// Branch and bound from an upper bound `best` reached by `bestMap`.
  void run(int best, std::vector<int> bestMap, long long maxExpansions) {
    best_ = best;
    bestMap_ = std::move(bestMap);
    maxExpansions_ = maxExpansions;
    rootBound_ = boundAfter(0);
    if (rootBound_ < best_) search(0, 0);
  }

  int best() const { return best_; }
  const std::vector<int>& bestMap() const { return bestMap_; }
  bool aborted() const { return aborted_; }
  long long expansions() const { return expansions_; }
  int rootBound() const { return rootBound_; }

 private:
  static constexpr int kUnmapped = -2;

  bool edge1(int u, int w) const { return adj1_[static_cast<std::size_t>(u) * n1_ + w] != 0; }
  bool edge2(int v, int w) const { return adj2_[static_cast<std::size_t>(v) * n2_ + w] != 0; }

  /// Highest degree first, then always the node with most edges to those already taken, so
  /// that edge costs are known early and the bound bites.
  static std::vector<int> connectedOrder(const Graph& g) {
    const int n = g.nodeCount();
    const std::vector<int> deg = degrees(g);
    const std::vector<char> adj = adjacency(g);
    std::vector<int> order, links(n, 0);
    std::vector<char> taken(n, 0);
    for (int step = 0; step < n; ++step) {
      int pick = -1;
      for (int v = 0; v < n; ++v) {
        if (taken[v]) continue;
        if (pick < 0 || std::tie(links[v], deg[v]) > std::tie(links[pick], deg[pick])) pick = v;
      }
      taken[pick] = 1;
      order.push_back(pick);
      for (int w = 0; w < n; ++w)
        if (adj[static_cast<std::size_t>(pick) * n + w]) ++links[w];
    }
    return order;
  }

  void search(int k, int cost) {
    if (aborted_) return;
    if (++expansions_ > maxExpansions_) {
      aborted_ = true;
      return;
    }
    const int u = order_[k];
    struct Option {
      int bound, target, step;
    };
    std::vector<Option> options;
    for (int v = -1; v < n2_; ++v) {
      if (v >= 0 && preimage_[v] >= 0) continue;
      int step = v < 0 ? 1 : 0;
      for (int p = 0; p < n1_; ++p) {
        if (image_[p] == kUnmapped) continue;
        const bool e2 = v >= 0 && image_[p] >= 0 && edge2(v, image_[p]);
        step += edge1(u, p) != e2;
      }
      assign(u, v);
      options.push_back({cost + step + boundAfter(k + 1), v, step});
      unassign(u, v);
    }
    std::stable_sort(options.begin(), options.end(), [](const Option& x, const Option& y) {
      return std::tie(x.bound, x.step) < std::tie(y.bound, y.step);
    });
    for (const Option& o : options) {
      if (o.bound >= best_ || aborted_) break;
      assign(u, o.target);
      if (k + 1 == n1_) {
        best_ = o.bound;  // the bound is exact once every node of a is placed
        bestMap_ = image_;
      } else {
        search(k + 1, cost + o.step);
      }
      unassign(u, o.target);
    }
  }

  void assign(int u, int v) {
    image_[u] = v;
    if (v >= 0) preimage_[v] = u;
  }
  void unassign(int u, int v) {
    image_[u] = kUnmapped;
    if (v >= 0) preimage_[v] = -1;
  }

  int n1_, n2_;
  std::vector<char> adj1_, adj2_;
  std::vector<int> order_, image_, preimage_;
  int best_ = 0, rootBound_ = 0;
  std::vector<int> bestMap_;
  long long expansions_ = 0, maxExpansions_ = 0;
  bool aborted_ = false;
};

}  // namespace

int editPathCost(const Graph& a, const Graph& b, const std::vector<int>& mapping) {
  const int n1 = a.nodeCount(), n2 = b.nodeCount();
  std::vector<int> preimage(n2, -1);
  int cost = 0;
  for (int u = 0; u < n1; ++u) {
    if (mapping[u] < 0) ++cost;  // deleted
    else preimage[mapping[u]] = u;
  }
  for (int v = 0; v < n2; ++v) cost += preimage[v] < 0;  // inserted
  const std::vector<char> adj1 = adjacency(a), adj2 = adjacency(b);
  for (const auto& [u, w] : a.edges) {
    const bool kept = mapping[u] >= 0 && mapping[w] >= 0 &&
                      adj2[static_cast<std::size_t>(mapping[u]) * n2 + mapping[w]];
    cost += !kept;
  }
  for (const auto& [v, x] : b.edges) {
    const bool kept = preimage[v] >= 0 && preimage[x] >= 0 &&
                      adj1[static_cast<std::size_t>(preimage[v]) * n1 + preimage[x]];
    cost += !kept;
  }
  return cost;
}

int improveMapping(const Graph& a, const Graph& b, std::vector<int>& mapping, int kicks) {
  // cost = |V1| + |V2| + |E1| + |E2| - 2 (mapped nodes + kept edges): maximise the bracket.
  const int n1 = a.nodeCount(), n2 = b.nodeCount();
  if (n1 == 0 || n2 == 0) return editPathCost(a, b, mapping);
  const std::vector<char> adj2 = adjacency(b);
  std::vector<std::vector<int>> nbr1(n1);
  for (const auto& [u, w] : a.edges) nbr1[u].push_back(w), nbr1[w].push_back(u);
  std::vector<int> map = mapping, preimage(n2, -1);
  for (int u = 0; u < n1; ++u)
    if (map[u] >= 0) preimage[map[u]] = u;
  // Edges at u kept if u's image were x (neighbour `skip` left out).
  auto kept = [&](int u, int x, int skip) {
    if (x < 0) return 0;
    int k = 0;
    for (int t : nbr1[u])
      if (t != skip && map[t] >= 0) k += adj2[static_cast<std::size_t>(x) * n2 + map[t]];
    return k;
  };
  auto swapImages = [&](int u, int w) {
    const int x = map[u], y = map[w];
    map[u] = y, map[w] = x;
    if (y >= 0) preimage[y] = u;
    if (x >= 0) preimage[x] = w;
  };
  auto descend = [&] {
    for (int pass = 0; pass < 1000; ++pass) {
      bool improved = false;
      for (int u = 0; u < n1; ++u) {
        // Move u to the best free node of b.
        int bestGain = 0, bestTarget = -1;
        const int here = kept(u, map[u], -1) + (map[u] >= 0);
        for (int v = 0; v < n2; ++v) {
          if (preimage[v] >= 0) continue;
          const int gain = kept(u, v, -1) + 1 - here;
          if (gain > bestGain) bestGain = gain, bestTarget = v;
        }
        if (bestTarget >= 0) {
          if (map[u] >= 0) preimage[map[u]] = -1;
          map[u] = bestTarget;
          preimage[bestTarget] = u;
          improved = true;
        }
        // Swap images with another node of a (the edge u-w, if any, is kept or not either way).
        for (int w = u + 1; w < n1; ++w) {
          const int x = map[u], y = map[w];
          if (x == y) continue;  // both deleted
          if (kept(u, y, w) + kept(w, x, u) > kept(u, x, w) + kept(w, y, u)) {
            swapImages(u, w);
            improved = true;
          }
        }
      }
      if (!improved) break;
    }
  };
  descend();
  int best = editPathCost(a, b, map);
  mapping = map;
  // Iterated local search: a few random swaps, descend again, keep the result unless worse.
  // Fixed seed: the same graphs always give the same answer.
  std::mt19937 rng(0x5eed);
  std::uniform_int_distribution<int> pick(0, n1 - 1);
  const int strength = std::max(2, n1 / 10);
  for (int kick = 0; kick < kicks && best > 0; ++kick) {
    for (int k = 0; k < strength; ++k) {
      const int u = pick(rng), w = pick(rng);
      if (u != w) swapImages(u, w);
    }
    descend();
    const int cost = editPathCost(a, b, map);
    if (cost <= best) {
      best = cost;
      mapping = map;
    } else {
      map = mapping;
      std::fill(preimage.begin(), preimage.end(), -1);
      for (int u = 0; u < n1; ++u)
        if (map[u] >= 0) preimage[map[u]] = u;
    }
  }
  return best;
}

namespace {

/// A node map for the full graphs from one between their degree-2 contractions: branch nodes
/// follow the small map, and where a contracted edge maps onto a contracted edge, the nodes
/// of the two chains are paired in order from the matched ends.
std::vector<int> liftThroughChains(const Contraction& ca, const Contraction& cb, const std::vector<int>& small,
                                   int n1) {
  std::vector<int> map(n1, -1);
  for (int i = 0; i < static_cast<int>(small.size()); ++i)
    if (small[i] >= 0) map[ca.kept[i]] = cb.kept[small[i]];
  const auto& edgesB = cb.graph.edges;
  for (std::size_t e = 0; e < ca.graph.edges.size(); ++e) {
    const auto [p, q] = ca.graph.edges[e];
    const int pb = small[p], qb = small[q];
    if (pb < 0 || qb < 0) continue;
    const auto key = std::minmax(pb, qb);
    const auto it = std::lower_bound(edgesB.begin(), edgesB.end(), std::make_pair(key.first, key.second));
    if (it == edgesB.end() || *it != std::make_pair(key.first, key.second)) continue;
    std::vector<int> chainB = cb.chains[it - edgesB.begin()];
    if (pb > qb) std::reverse(chainB.begin(), chainB.end());  // walk it from p's image
    const std::vector<int>& chainA = ca.chains[e];
    for (std::size_t i = 0; i < std::min(chainA.size(), chainB.size()); ++i) map[chainA[i]] = chainB[i];
  }
  return map;
}

int kicksFor(const Graph& a, const Graph& b) {
  // About the same work for every size: fewer rounds on large graphs.
  return std::clamp(20000 / std::max(1, std::max(a.nodeCount(), b.nodeCount())), 30, 300);
}

/// The bipartite method from a to b only (the heuristic is not symmetric).
GedResult bipartiteOneWay(const Graph& a, const Graph& b) {
  EditSearch search(a, b);
  GedResult r;
  r.method = "bipartite";
  r.lowerBound = search.boundAfter(0, &r.mapping);
  r.assignmentCost = editPathCost(a, b, r.mapping);
  r.distance = improveMapping(a, b, r.mapping, kicksFor(a, b));
  // Second start for skeleton-like graphs (long chains of degree-2 nodes): solve the
  // contracted graphs, lift that map along the chains, improve it the same way.
  const Contraction ca = contractWithChains(a), cb = contractWithChains(b);
  if (r.distance > r.lowerBound &&
      (ca.graph.nodeCount() < a.nodeCount() || cb.graph.nodeCount() < b.nodeCount())) {
    GedOptions inner;
    inner.maxExpansions = 200000;  // a start only: no need to prove the small map optimal
    inner.mipMaxColumns = 0;       // nor by the binary program
    const GedResult small = graphEditDistance(ca.graph, cb.graph, inner);
    std::vector<int> lifted = liftThroughChains(ca, cb, small.mapping, a.nodeCount());
    const int cost = improveMapping(a, b, lifted, kicksFor(a, b));
    if (cost < r.distance) {
      r.distance = cost;
      r.mapping = std::move(lifted);
    }
  }
  // Third start: node i to node i. Graphs built in a canonical order (ACD skeletons of an
  // invariant decomposition under a rigid motion) correspond this way, which the assignment
  // can miss among many look-alike nodes. Any mapping is an edit path: this only tightens.
  if (r.distance > r.lowerBound) {
    std::vector<int> identity(a.nodeCount(), -1);
    for (int u = 0; u < std::min(a.nodeCount(), b.nodeCount()); ++u) identity[u] = u;
    const int cost = improveMapping(a, b, identity, kicksFor(a, b));
    if (cost < r.distance) {
      r.distance = cost;
      r.mapping = std::move(identity);
    }
  }
  return r;
}

}  // namespace

GedResult bipartiteGed(const Graph& a, const Graph& b) {
  const auto start = acd::Clock::now();
  // Both directions, the better path kept: the reported distance is symmetric.
  GedResult r = bipartiteOneWay(a, b);
  const GedResult back = bipartiteOneWay(b, a);
  r.lowerBound = std::max(r.lowerBound, back.lowerBound);  // both are lower bounds of the same distance
  if (back.distance < r.distance) {
    r.distance = back.distance;
    r.mapping.assign(a.nodeCount(), -1);
    for (int v = 0; v < b.nodeCount(); ++v)
      if (back.mapping[v] >= 0) r.mapping[back.mapping[v]] = v;
  }
  r.assignmentCost = std::min(r.assignmentCost, back.assignmentCost);
  r.exact = r.distance == r.lowerBound;  // the bounds met: proven
  r.seconds = acd::secondsSince(start);
  return r;
}

GedResult exactGed(const Graph& a, const Graph& b, long long maxExpansions) {
  const auto start = acd::Clock::now();
  const GedResult seed = bipartiteGed(a, b);
  EditSearch search(a, b);
  search.run(seed.distance, seed.mapping, maxExpansions);
  GedResult r;
  r.method = "exact";
  r.assignmentCost = seed.assignmentCost;
  r.exact = !search.aborted();
  r.distance = search.best();
  r.mapping = search.bestMap();
  r.lowerBound = r.exact ? r.distance : std::max(search.rootBound(), seed.lowerBound);
  r.expansions = search.expansions();
  r.seconds = acd::secondsSince(start);
  return r;
}

GedResult graphEditDistance(const Graph& a, const Graph& b, const GedOptions& options) {
  const bool small = a.nodeCount() <= options.exactMaxNodes && b.nodeCount() <= options.exactMaxNodes;
  GedResult r = small ? exactGed(a, b, options.maxExpansions) : bipartiteGed(a, b);
  const long long columns = 1LL * a.nodeCount() * b.nodeCount() + 1LL * a.edges.size() * b.edges.size();
  if (!r.exact && columns <= options.mipMaxColumns) {
    const double before = r.seconds;
    r = mipGed(a, b, r, options.mipMaxBranchNodes, options.mipMaxIterations);
    r.seconds += before;
  }
  return r;
}

}  // namespace skeleton
