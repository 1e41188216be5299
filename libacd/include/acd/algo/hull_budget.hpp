// A budget on the number of hulls: after a decomposition, components are merged, cheapest
// first, until at most N remain. Simulators want this (PhysX on the GPU: at most 64 hulls per
// body), and it is V-HACD's and CoACD's "maximum number of hulls".
//
// The cost of a merge is the concavity of the union, so that the largest concavity over the
// components grows as little as possible, ties going to the smaller growth of hull volume.
// - Neighbours that share cut faces are glued along them (acd/algo/merge.hpp) and the union's
//   concavity is measured like any component's (acd/algo/concavity.hpp, the decomposition's own
//   measure and epsilon): the reported concavity can be compared with tau.
// - Pieces that share no face (separate pieces of the input, or a glue that would not give a
//   closed, connected mesh) are merged only when no neighbour pair is left. Their union is not
//   one closed surface, so its concavity cannot be measured; the cost is then the hull gap: the
//   largest distance from the merged hull's surface to the pieces (acd::evaluate's "hulls stick
//   out", on the union of the pieces), which is the thickness of what the hull adds between
//   them. Such components are flagged.
// The merge order depends on neither the thread count nor the input's pose.
#pragma once

#include <acd/decompose.hpp>
#include <acd/status.hpp>

#include <vector>

namespace acd {

struct HullBudgetOptions {
  int maxHulls = 64;  // N >= 1
  int threads = 0;    // 0: all cores; the result does not depend on it
};

struct HullBudgetReport {
  Status status;                           // InvalidParameter for N < 1 or a failed decomposition
  int before = 0;                          // components on entry
  int after = 0;
  int gluedMerges = 0;                     // along shared cut faces
  int joinedMerges = 0;                    // of pieces that share no face (hull gap measure)
  std::vector<std::vector<int>> members;   // per component after: the components on entry it holds
  std::vector<bool> hullGapMeasure;        // per component after: its concavity is the hull gap
  double maxConcavity = 0.0;               // over the components after, normalised units
  double tau = 0.0;                        // the decomposition's
  bool exceedsTau = false;                 // maxConcavity > tau
  double seconds = 0.0;
};

/// Merges components of `d` in place (mesh, hull, volumes, concavity, depth) until at most
/// `maxHulls` remain; nothing happens when there are no more than that already.
HullBudgetReport limitHullCount(Decomposition& d, const HullBudgetOptions& options = {});

}  // namespace acd
