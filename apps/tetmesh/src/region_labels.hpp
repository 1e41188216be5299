// Which region of the hull complex a point lies in: the labelling that the Delaunay refinement
// (region_refiner.hpp) meshes. It replaces an explicit complex of facets: the regions' small
// features (outlines crossing near a corner, faces a hair apart, thin overlaps) are never made
// into facets, so they cannot force short edges or slivers into the mesh.
//
// A region is a closed convex triangle mesh, stored as the half-spaces of its faces; a point's
// excess over a region is the largest of its signed distances to those planes (negative inside,
// and a lower bound on the distance to the region outside).
//  * Inside one region: its label. Inside several (hulls of merged components, self-intersecting
//    input): the region it is deepest in, so an overlap is split where the depths are equal.
//  * Outside every region but in a gap narrower than `closedGap` between two regions that face
//    each other across it (the planes it lies beyond point at each other): the nearer region.
//    Two faces a hair apart become one interface; nothing grows where a region faces the open.
//  * Otherwise 0 (outside).
// Ties go to the lower label, so the result does not depend on the order of the tests.
#pragma once

#include <acd/algo/plane.hpp>
#include <acd/mesh.hpp>

#include <vector>

namespace tetmesh {

using acd::Vec3;

class RegionLabels {
 public:
  /// `regions[i]` gets label i + 1; an empty region is never a point's label.
  RegionLabels(const std::vector<acd::TriMesh>& regions, double closedGap);

  int operator()(const Vec3& p) const;

  /// The box of all regions, widened by the gap.
  const Vec3& lower() const { return lower_; }
  const Vec3& upper() const { return upper_; }

 private:
  using Plane = acd::HalfSpace;  // unit normal
  struct Region {
    std::vector<Plane> planes;
    Vec3 lower, upper;  // box, widened by the gap
  };
  /// The largest signed distance of p to region r's planes, and the plane where it is reached;
  /// stops early (returning a value above `stopAbove`) once the excess is known to exceed it.
  double excess(const Region& r, const Vec3& p, double stopAbove, const Plane** beyond) const;

  std::vector<Region> regions_;
  double gap_ = 0.0;
  Vec3 lower_ = Vec3::Zero(), upper_ = Vec3::Zero();
};

}  // namespace tetmesh
