// A bridge of the concavity measure (Lien & Amato 2007, Section 4.1): a patch of convex-hull
// facets and the supporting plane they share within epsilon. The concavity measure builds them;
// the open-surface projection and the cut-plane choice read them.
#pragma once

#include <acd/mesh.hpp>

#include <algorithm>
#include <vector>

namespace acd {

/// A bridge patch: contiguous hull facets and their supporting plane n.x = offset.
struct Bridge {
  Vec3 normal = Vec3::Zero();    // unit, outward
  double offset = 0.0;
  std::vector<int> hullFaces;
  int seedFace = -1;             // hull facet whose plane is the supporting plane

  /// Concavity of a point in this bridge's pocket: its distance below the supporting plane.
  double concavityOf(const Vec3& p) const { return std::max(0.0, offset - normal.dot(p)); }
};

}  // namespace acd
