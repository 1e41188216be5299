// CGAL's exact point-in-mesh test (Side_of_triangle_mesh), the baseline of --compare.
#pragma once

#include <acd/mesh.hpp>

#include <memory>
#include <string>

namespace pointloc {

/// CGAL::Side_of_triangle_mesh over the model (Surface_mesh, exact predicates, AABB tree of
/// the faces, ray shooting). Kept behind this wrapper so CGAL's headers compile in one file.
/// Thread-safe after construction (the tree is built in the constructor).
class CgalSideOfMesh {
 public:
  explicit CgalSideOfMesh(const acd::TriMesh& mesh);
  ~CgalSideOfMesh();
  CgalSideOfMesh(const CgalSideOfMesh&) = delete;
  CgalSideOfMesh& operator=(const CgalSideOfMesh&) = delete;

  /// False when the mesh could not be turned into a CGAL surface (see `error`).
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  /// Seconds spent building the mesh and its AABB tree.
  double buildSeconds() const { return buildSeconds_; }

  /// Inside or on the surface.
  bool inside(const acd::Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string error_;
  double buildSeconds_ = 0.0;
};

}  // namespace pointloc
