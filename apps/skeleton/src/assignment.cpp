// Kuhn-Munkres as shortest augmenting paths with row and column potentials: one row is added
// per round, so the whole solve is O(n^3).
#include "assignment.hpp"

#include <limits>

namespace skeleton {

std::vector<int> solveAssignment(const std::vector<double>& cost, int n, double* total) {
  const double inf = std::numeric_limits<double>::infinity();
  // 1-based internally; column 0 is the virtual start of each augmenting path.
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> rowOfColumn(n + 1, 0), way(n + 1, 0);
  for (int i = 1; i <= n; ++i) {
    rowOfColumn[0] = i;
    int j0 = 0;
    std::vector<double> minv(n + 1, inf);
    std::vector<char> used(n + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = rowOfColumn[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = cost[(i0 - 1) * n + (j - 1)] - u[i0] - v[j];
        if (cur < minv[j]) minv[j] = cur, way[j] = j0;
        if (minv[j] < delta) delta = minv[j], j1 = j;
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) u[rowOfColumn[j]] += delta, v[j] -= delta;
        else minv[j] -= delta;
      }
      j0 = j1;
    } while (rowOfColumn[j0] != 0);
    do {
      const int j1 = way[j0];
      rowOfColumn[j0] = rowOfColumn[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> columnOfRow(n, -1);
  double sum = 0.0;
  for (int j = 1; j <= n; ++j) {
    columnOfRow[rowOfColumn[j] - 1] = j - 1;
    sum += cost[(rowOfColumn[j] - 1) * n + (j - 1)];
  }
  if (total) *total = sum;
  return columnOfRow;
}

}  // namespace skeleton
