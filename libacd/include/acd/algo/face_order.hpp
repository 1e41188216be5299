// Whether two triangles list the same corners in the same cyclic order (the same face, seen
// from the same side), as the repair and the diagnosis both ask of duplicate faces.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

inline bool sameCyclicOrder(const Face& a, const Face& b) {
  for (int r = 0; r < 3; ++r)
    if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
  return false;
}

}  // namespace acd
