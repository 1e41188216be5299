// Faces given more than once: exact copies, and faces given in both orientations (double-sided
// faces, as exporters write thin sheets and the walls between cells). The repair resolves them,
// and so does the measure of the input as read (acd/algo/shell_inside.hpp): neither moves a point.
#pragma once

#include <acd/mesh.hpp>
#include <vector>

namespace acd {

struct DuplicateOutcome {
  std::vector<Face> faces;  // in their order, the dropped ones left out
  int exactCopies = 0, keptOne = 0, droppedBoth = 0;
};

/// Exact copies go. A face present in both orientations is a double-sided face: a connected set
/// of them (joined across edges no other face uses) whose outer edges all lie where the rest of
/// the mesh is already closed (an even, non-zero number of other faces) is an inner wall that
/// closes nothing, and goes entirely; otherwise one side of each stays (it closes a hole, or it
/// is a sheet that is part of the shape), the one the file gives first.
DuplicateOutcome resolveDuplicates(const std::vector<Face>& faces);

}  // namespace acd
