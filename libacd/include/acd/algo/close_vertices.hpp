// Vertices closer than a tolerance: the repair's first step (merging them) and the measure of the
// input as read (which welds what the repair would) share one definition.
#pragma once

#include <acd/mesh.hpp>
#include <vector>

namespace acd {

/// Per vertex, the lowest-numbered vertex within `tolerance` of it through a chain of close
/// vertices (`box` bounds them all).
std::vector<int> closeVertexRoots(const std::vector<Vec3>& vertices, const Box3& box, double tolerance);

}  // namespace acd
