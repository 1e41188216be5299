// A point strictly inside each closed piece of a robot. They stand for the robot in point
// location: OMPL.app puts a robot's reference point at the mean of its vertices, which lies
// outside a ring, a U or two bars joined at an angle, so no test may rely on it being inside.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace planner {

/// One point per piece (closed, outward), strictly inside it: `preferred` where that piece
/// contains it, else the middle of the piece's thickest inward chord (from the centres of its
/// largest faces, along their inward normals). Pieces with no inside (flat, open) get none.
std::vector<acd::Vec3> insidePoints(const std::vector<acd::TriMesh>& pieces, const acd::Vec3& preferred);

}  // namespace planner
