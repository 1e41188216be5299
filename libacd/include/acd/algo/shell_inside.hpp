// Inside the input as the user gave it: inside any of its closed shells, each tested on its own.
// The promise (every hull within tau of the input) is measured against this solid, not against
// the repaired model, so that no repair, wrap, union or dropped cavity can hide a hull that stands
// off what the user has.
#pragma once

#include <acd/mesh.hpp>
#include <memory>

namespace acd {

/// The solid of a triangle soup: the union of what its shells bound. Vertices within `weld` (a
/// fraction of the bounding box's diagonal: the repair's own merge, which moves nothing that
/// matters) are welded first, and faces given twice are resolved as the repair resolves them
/// (acd/algo/duplicate_faces.hpp: a copy goes; of a face given in both orientations one side
/// stays, or neither when the two form an inner wall): exporters split vertices along texture
/// seams, repeat faces and write closed shells on both sides. A shell is an edge-connected
/// piece. It is closed when every edge is used as often in one direction as in the other
/// (touching solids that share an edge included), or is a closed, orientable manifold with some
/// faces flipped (oriented again here), once loose flaps are peeled off (faces with an edge no
/// other face uses, repeatedly: a fin welded to a box). A closed shell bounds what its exact
/// winding number says, whatever its orientation; each shell is tested on its own (exporters
/// flip shells, and overlapping shells would cancel in one winding number over the whole). An
/// open shell bounds where its generalised winding number is at least 1/2 in magnitude: a box
/// without its lid bounds the box, whose hole a hull may span; a flat sheet bounds nothing. That
/// winding number is the one of the shell closed up by a cone over its rim (an integer a ray
/// counts exactly) less the cone's own (summed face by face), so its cost follows the rim, not the
/// shell: a scan of a million faces with a few holes is as quick as a closed one. Past 50,000
/// rim edges of open shells all together the rest count as surface only. Thread-safe after
/// construction.
class ShellsInside {
 public:
  explicit ShellsInside(const TriMesh& soup, double weld = 1e-6);
  ~ShellsInside();
  ShellsInside(const ShellsInside&) = delete;
  ShellsInside& operator=(const ShellsInside&) = delete;

  bool inside(const Vec3& q) const { return insideClosed(q) || insideOpen(q); }
  /// Inside a closed shell: a ball around q that meets no face is inside too.
  bool insideClosed(const Vec3& q) const;
  /// Inside an open shell by its winding number, which varies off the faces (across a missing
  /// lid): no ball around q is known to be inside. Costs a sum over the open shells' faces.
  bool insideOpen(const Vec3& q) const;
  int solidShells() const;        // the shells that bound a solid
  int openShells() const;         // the shells that do not bound a solid
  int surfaceOnlyShells() const;  // of those, the ones past the winding number's face budget

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acd
