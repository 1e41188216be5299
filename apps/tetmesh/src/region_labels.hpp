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
//  * Outside every region but in a gap narrower than the closed gap of both regions between two
//    regions that face each other across it (the planes it lies beyond point at each other): the
//    nearer region.
//    Two faces a hair apart become one interface; nothing grows where a region faces the open.
//  * Otherwise 0 (outside).
// Ties go to the lower label, so the result does not depend on the order of the tests.
#pragma once

#include <acd/algo/plane.hpp>
#include <acd/mesh.hpp>

#include <limits>
#include <vector>

namespace tetmesh {

using acd::Vec3;

class RegionLabels {
 public:
  /// `regions[i]` gets label i + 1; an empty region is never a point's label. A gap closes
  /// between two regions when it is narrower than both regions' `closedGaps`.
  RegionLabels(const std::vector<acd::TriMesh>& regions, const std::vector<double>& closedGaps);
  RegionLabels(const std::vector<acd::TriMesh>& regions, double closedGap)
      : RegionLabels(regions, std::vector<double>(regions.size(), closedGap)) {}

  int operator()(const Vec3& p) const;

  int regions() const { return static_cast<int>(regions_.size()); }
  /// The region's smallest width (the least extent along one of its facet normals); 0 if empty.
  double width(int i) const { return regions_[i].width; }
  /// The largest signed distance of p to region i's facet planes (negative inside).
  double excess(int i, const Vec3& p) const {
    const Plane* beyond = nullptr;
    return excess(regions_[i], p, std::numeric_limits<double>::infinity(), &beyond);
  }
  /// Whether p lies in region i's box widened by its gap.
  bool nearBox(int i, const Vec3& p) const {
    const Region& r = regions_[i];
    return !r.planes.empty() && (p.array() >= r.lower.array()).all() && (p.array() <= r.upper.array()).all();
  }

  /// The box of all regions, widened by the gap.
  const Vec3& lower() const { return lower_; }
  const Vec3& upper() const { return upper_; }

 private:
  using Plane = acd::HalfSpace;  // unit normal
  struct Region {
    std::vector<Plane> planes;
    Vec3 lower, upper;  // box, widened by the gap
    double gap = 0.0;
    double width = 0.0;
  };
  /// The largest signed distance of p to region r's planes, and the plane where it is reached;
  /// stops early (returning a value above `stopAbove`) once the excess is known to exceed it.
  double excess(const Region& r, const Vec3& p, double stopAbove, const Plane** beyond) const;

  std::vector<Region> regions_;
  double gap_ = 0.0;  // the largest region's gap
  Vec3 lower_ = Vec3::Zero(), upper_ = Vec3::Zero();
};

}  // namespace tetmesh
