#include "ged_mip.hpp"

#include <acd/algo/stopwatch.hpp>
#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace skeleton {

namespace {

/// The program's columns: x[i][k] first, then y[e][f] (GLPK counts from 1).
struct Columns {
  int n1, n2, m1, m2;
  int x(int i, int k) const { return 1 + i * n2 + k; }
  int y(int e, int f) const { return 1 + n1 * n2 + e * m2 + f; }
  int count() const { return n1 * n2 + m1 * m2; }
};

/// What the branch-and-bound callback needs and what it finds out.
struct Search {
  std::vector<double> seedPoint;  // the seed path as a point of the program, GLPK-indexed
  bool seeded = false;
  int maxBranchNodes = 0;
  int maxIterations = 0;
  double bestBound = std::numeric_limits<double>::infinity();  // on matched nodes + edges
};

void callback(glp_tree* tree, void* info) {
  auto& search = *static_cast<Search*>(info);
  if (glp_ios_reason(tree) == GLP_IHEUR && !search.seeded) {
    search.seeded = true;
    glp_ios_heur_sol(tree, search.seedPoint.data());
  }
  if (const int node = glp_ios_best_node(tree); node != 0)
    search.bestBound = std::min(search.bestBound, glp_ios_node_bound(tree, node));
  int active = 0, current = 0, total = 0;
  glp_ios_tree_size(tree, &active, &current, &total);
  if (total > search.maxBranchNodes || glp_get_it_cnt(glp_ios_get_prob(tree)) > search.maxIterations)
    glp_ios_terminate(tree);
}

/// Per node, the indices of the edges at it.
std::vector<std::vector<int>> edgesAtNodes(const Graph& g) {
  std::vector<std::vector<int>> at(g.nodeCount());
  for (int e = 0; e < static_cast<int>(g.edges.size()); ++e) {
    at[g.edges[e].first].push_back(e);
    at[g.edges[e].second].push_back(e);
  }
  return at;
}

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

}  // namespace

GedResult mipGed(const Graph& a, const Graph& b, const GedResult& seed, int maxBranchNodes, int maxIterations) {
  const auto start = acd::Clock::now();
  const Columns col{a.nodeCount(), b.nodeCount(), static_cast<int>(a.edges.size()), static_cast<int>(b.edges.size())};
  const int total = col.n1 + col.n2 + col.m1 + col.m2;
  GedResult r = seed;
  r.method = "mip";
  if (col.n1 == 0 || col.n2 == 0) return r;  // nothing to match: the seed's path is the only one

  std::unique_ptr<glp_prob, ProblemDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MAX);
  glp_add_cols(lp.get(), col.count());
  for (int j = 1; j <= col.count(); ++j) {
    glp_set_col_kind(lp.get(), j, GLP_BV);
    glp_set_obj_coef(lp.get(), j, 1.0);
  }
  std::vector<int> rowIndex{0}, colIndex{0};
  std::vector<double> value{0.0};
  int rows = 0;
  auto addRow = [&](const std::vector<std::pair<int, double>>& terms, double upper) {
    ++rows;
    for (const auto& [c, v] : terms) rowIndex.push_back(rows), colIndex.push_back(c), value.push_back(v);
    glp_add_rows(lp.get(), 1);
    glp_set_row_bnds(lp.get(), rows, GLP_UP, 0.0, upper);
  };
  for (int i = 0; i < col.n1; ++i) {
    std::vector<std::pair<int, double>> terms;
    for (int k = 0; k < col.n2; ++k) terms.push_back({col.x(i, k), 1.0});
    addRow(terms, 1.0);
  }
  for (int k = 0; k < col.n2; ++k) {
    std::vector<std::pair<int, double>> terms;
    for (int i = 0; i < col.n1; ++i) terms.push_back({col.x(i, k), 1.0});
    addRow(terms, 1.0);
  }
  const std::vector<std::vector<int>> edgesAt1 = edgesAtNodes(a), edgesAt2 = edgesAtNodes(b);
  for (int e = 0; e < col.m1; ++e)  // edge e = {i, j} onto edges at k only if i or j goes to k
    for (int k = 0; k < col.n2; ++k) {
      if (edgesAt2[k].empty()) continue;
      std::vector<std::pair<int, double>> terms{{col.x(a.edges[e].first, k), -1.0}, {col.x(a.edges[e].second, k), -1.0}};
      for (int f : edgesAt2[k]) terms.push_back({col.y(e, f), 1.0});
      addRow(terms, 0.0);
    }
  for (int f = 0; f < col.m2; ++f)  // and the same from the second graph's side
    for (int i = 0; i < col.n1; ++i) {
      if (edgesAt1[i].empty()) continue;
      std::vector<std::pair<int, double>> terms{{col.x(i, b.edges[f].first), -1.0}, {col.x(i, b.edges[f].second), -1.0}};
      for (int e : edgesAt1[i]) terms.push_back({col.y(e, f), 1.0});
      addRow(terms, 0.0);
    }
  glp_load_matrix(lp.get(), static_cast<int>(value.size()) - 1, rowIndex.data(), colIndex.data(), value.data());

  // The seed as a point of the program: its matched nodes, and the edges whose ends it matches.
  Search search;
  search.maxBranchNodes = maxBranchNodes;
  search.maxIterations = maxIterations;
  search.seedPoint.assign(col.count() + 1, 0.0);
  if (static_cast<int>(seed.mapping.size()) == col.n1) {
    for (int i = 0; i < col.n1; ++i)
      if (seed.mapping[i] >= 0) search.seedPoint[col.x(i, seed.mapping[i])] = 1.0;
    for (int e = 0; e < col.m1; ++e) {
      const int k = seed.mapping[a.edges[e].first], l = seed.mapping[a.edges[e].second];
      if (k < 0 || l < 0) continue;
      for (int f : edgesAt2[k])
        if (b.edges[f].first == l || b.edges[f].second == l) search.seedPoint[col.y(e, f)] = 1.0;
    }
  }

  glp_smcp simplex;
  glp_init_smcp(&simplex);
  simplex.msg_lev = GLP_MSG_OFF;
  simplex.it_lim = maxIterations;
  if (glp_simplex(lp.get(), &simplex) != 0 || glp_get_status(lp.get()) != GLP_OPT) return r;
  // The relaxation alone bounds the matching from above.
  search.bestBound = glp_get_obj_val(lp.get());
  glp_iocp options;
  glp_init_iocp(&options);
  options.msg_lev = GLP_MSG_OFF;
  options.cb_func = callback;
  options.cb_info = &search;
  const int code = glp_intopt(lp.get(), &options);
  const int status = glp_mip_status(lp.get());

  auto costOf = [total](double matched) { return total - 2 * static_cast<int>(std::lround(matched)); };
  if (status == GLP_OPT || status == GLP_FEAS) {
    std::vector<int> mapping(col.n1, -1);
    for (int i = 0; i < col.n1; ++i)
      for (int k = 0; k < col.n2; ++k)
        if (glp_mip_col_val(lp.get(), col.x(i, k)) > 0.5) mapping[i] = k;
    // The path the matching induces, costed on its own: at most what the program says.
    const int found = std::min(costOf(glp_mip_obj_val(lp.get())), editPathCost(a, b, mapping));
    if (found < r.distance) r.distance = found, r.mapping = mapping;
  }
  if (code == 0 && status == GLP_OPT) {
    r.lowerBound = r.distance;
  } else {
    // Matched nodes + edges are whole: the bound rounds down.
    const int bound = total - 2 * static_cast<int>(std::floor(search.bestBound + 1e-6));
    r.lowerBound = std::max(r.lowerBound, std::min(bound, r.distance));
  }
  r.exact = r.lowerBound == r.distance;
  r.seconds = acd::secondsSince(start);
  return r;
}

}  // namespace skeleton
