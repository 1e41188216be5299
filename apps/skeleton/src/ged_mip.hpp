// Exact graph edit distance of mid-sized graphs (tens of nodes: contracted skeletons) as a binary
// linear program, solved by GLPK's branch and bound.
//
// With unit deletion/insertion costs and free substitutions, an edit path is a partial matching
// of nodes together with the edges it carries over, and
//   cost = n1 + n2 + m1 + m2 - 2 * (matched nodes + matched edges).
// The program (Lerouge, Abu-Aisheh, Raveaux, Héroux and Adam, "New binary linear programming
// formulation to compute the graph edit distance", Pattern Recognition 72, 2017, formulation F2,
// for undirected edges): x[i][k] = node i of the first graph matched to node k of the second,
// y[e][f] = edge e matched to edge f; maximise sum x + sum y subject to
//   each node matched at most once on either side,
//   for every edge e = {i, j} and node k:  sum of y[e][f] over edges f at k <= x[i][k] + x[j][k],
//   for every edge f = {k, l} and node i:  sum of y[e][f] over edges e at i <= x[i][k] + x[i][l],
// so an edge is matched only onto an edge whose two ends are the images of its own.
// The search starts from a known edit path (the bipartite answer) and stops after a number of
// branch-and-bound nodes or simplex iterations; the best bound of the open nodes then still gives a
// proven lower bound. Counts rather than a time limit: the same graphs give the same answer on any
// machine.
#pragma once

#include "ged.hpp"

namespace skeleton {

/// Exact distance by the program above, started from `seed` (an edit path: its mapping and
/// distance) and stopped after `maxBranchNodes` branch-and-bound nodes or `maxIterations` simplex
/// iterations in all (the relaxation included). `exact` when the search
/// finished or its bound met the best path; `lowerBound` is never below seed.lowerBound.
GedResult mipGed(const Graph& a, const Graph& b, const GedResult& seed, int maxBranchNodes = 1000,
                 int maxIterations = 100000);

}  // namespace skeleton
