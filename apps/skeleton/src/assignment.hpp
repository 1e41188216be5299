// Minimum-cost assignment (Hungarian algorithm, Kuhn-Munkres with potentials, O(n^3)).
#pragma once

#include <vector>

namespace skeleton {

/// Square cost matrix, row-major, n*n. Returns for each row the column it is assigned to, and
/// the total cost in `total`. Costs must be finite.
std::vector<int> solveAssignment(const std::vector<double>& cost, int n, double* total = nullptr);

}  // namespace skeleton
