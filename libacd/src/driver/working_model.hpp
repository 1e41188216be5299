// The recursion's side of the working mesh (acd/algo/working_mesh.hpp): the first pieces replaced
// by their working meshes, and, once the pieces are final, the input's own vertices each final
// piece stands for, so that its hull is built from the input's surface, not only the working one.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

struct WorkingModel {
  std::vector<std::vector<Vec3>> inputVertices;  // by first piece, where simplified (else empty)
  double distance = 0.0;                         // the largest distance the simplification measured, either way
  int inputFaces = 0, workingFaces = 0;
  bool used() const { return workingFaces < inputFaces; }
};

/// Replaces each mesh by its working mesh within `tolerance` (in parallel; the same for any thread
/// count) where that has fewer faces.
WorkingModel simplifyPieces(std::vector<TriMesh>& meshes, double tolerance);

/// For each final piece (its mesh and the first piece it came from), the input vertices nearest to
/// it: each input vertex goes to the final piece of its first piece whose surface is nearest (equal
/// distances, as on a cut face two pieces share, to the piece listed first).
std::vector<std::vector<Vec3>> inputVerticesOf(const WorkingModel& working, const std::vector<const TriMesh*>& finals,
                                               const std::vector<int>& sources);

}  // namespace acd
