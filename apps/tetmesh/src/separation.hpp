// Where two convex point sets are apart: the separating-axis test restricted to the facet
// normals of their hulls. Used to find the planes along which hull regions touch (the cut
// planes of the decomposition) and the planes that keep grown regions apart.
#pragma once

#include <acd/algo/convex_polytope.hpp>
#include <acd/mesh.hpp>

#include <limits>
#include <vector>

namespace tetmesh {

using acd::Vec3;
using acd::maxAlong;            // support functions and facet normals live in libacd
using acd::minAlong;
using acd::uniqueFacetNormals;

/// Least-squares plane through points; normal oriented like `hint`. False if they are not
/// spread in two directions.
bool fitPlane(const std::vector<Vec3>& pts, const Vec3& hint, Vec3& normal);

/// `gap` > 0 is a clearance, < 0 the depth of an overlap, along `normal` (from the first set
/// toward the second); the plane n . x = offset lies halfway between the two sets.
struct Contact {
  double gap = std::numeric_limits<double>::infinity();
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;
};

/// The facet normal of either set (`ni`, `nj`: their hulls' unique facet normals) along which
/// the sets are farthest apart. For sets touching within `tol`, the plane is refitted to the
/// points of both near it (their shared cut section): hull facets of nearly collinear corners
/// have inaccurate normals.
Contact findContact(const std::vector<Vec3>& vi, const std::vector<Vec3>& vj, const std::vector<Vec3>& ni,
                    const std::vector<Vec3>& nj, double tol);

}  // namespace tetmesh
