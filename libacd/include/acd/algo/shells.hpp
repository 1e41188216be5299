// Several closed shells in one model: which lie inside which (cavities), and which overlap.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

struct ShellNesting {
  std::vector<int> depth;      // per shell: how many other shells contain it
  std::vector<char> overlaps;  // per shell: it passes through (or touches) another shell
  int cavities = 0;            // shells at odd depth
  int overlapping = 0;         // shells with overlaps set
};

/// Classifies closed, consistently oriented shells. Shell A contains shell B when B's box lies
/// in A's and every sampled vertex of B (up to 64, spread over B) is inside A (exact
/// point-in-solid test, acd/algo/inside.hpp); when only some are, the two overlap. Under the even-odd
/// rule a shell at odd depth bounds a cavity (a void inside a solid, whichever way the file
/// orients it); at even depth it is a solid, possibly inside another's cavity. Touching shells
/// (vertices exactly on the other's surface) count as overlapping or apart; both are decomposed
/// per shell, so either answer gives the same decomposition.
ShellNesting classifyShells(const std::vector<TriMesh>& shells);

}  // namespace acd
