// Inside the input as the user gave it: inside any of its closed shells, each tested on its own.
// The promise (every hull within tau of the input) is measured against this solid, not against
// the repaired model, so that no repair, wrap, union or dropped cavity can hide a hull that stands
// off what the user has.
#pragma once

#include <acd/mesh.hpp>

#include <memory>

namespace acd {

/// The solid of a triangle soup: the union of what its closed shells bound. Vertices within
/// `weld` (a fraction of the bounding box's diagonal; the repair's own merge, which moves nothing
/// that matters) are welded first, and a face repeated with the same orientation kept once:
/// exporters split vertices along texture seams and repeat faces. A shell is an
/// edge-connected piece; it bounds a solid when every edge is used as often in one direction as in
/// the other (touching solids that share an edge included), or when it is a closed, orientable
/// manifold with some faces flipped (oriented again here). Each shell is tested on its own and
/// whatever its orientation (exporters flip shells; overlapping shells would cancel in one
/// winding number over the whole). Open shells bound nothing: near them only the surface counts.
/// Thread-safe after construction.
class ShellsInside {
 public:
  explicit ShellsInside(const TriMesh& soup, double weld = 1e-6);
  ~ShellsInside();
  ShellsInside(const ShellsInside&) = delete;
  ShellsInside& operator=(const ShellsInside&) = delete;

  bool inside(const Vec3& q) const;
  int solidShells() const;  // the shells that bound a solid
  int openShells() const;   // the shells that do not (surface only)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acd
