// Openings: the cut faces between neighbouring ACD components of the free space. Narrow
// passages sit there (Lien & Amato 2007, Section 7, "Motion planning").
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace planner {

struct Opening {
  int a = -1, b = -1;            // neighbouring components, a < b
  acd::Vec3 centroid = acd::Vec3::Zero();  // area-weighted
  acd::Vec3 normal = acd::Vec3::Zero();    // unit, pointing from a into b
  double area = 0.0;
  double radius = 0.0;           // largest distance from the centroid to a corner
  acd::Vec3 extentLo = acd::Vec3::Zero(), extentHi = acd::Vec3::Zero();  // bounding box
  acd::TriMesh triangles;        // the shared region, oriented like a's boundary (outward of a)
};

/// The shared regions between the components of a decomposed closed solid `whole`. A face
/// of component i is a cut face when a point just outside it (along its normal) is still
/// inside `whole`; the component containing that point is its neighbour. Working from the
/// geometry, not from matching triangles, keeps a cap that was split later on one side only.
/// Openings come sorted by decreasing area; pairs that touch with zero area are dropped.
std::vector<Opening> extractOpenings(const acd::TriMesh& whole, const std::vector<acd::TriMesh>& components);

}  // namespace planner
