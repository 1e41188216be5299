// Poses aligned to the openings of the free space's ACD. A passage that is narrow in rotation
// (a slot the robot fits only lengthwise, and only with its wide side along the slot) is a thin
// set of orientations: random ones almost never fit. A motion-planning expert would pass the
// robot through the slot long axis first, its cross-section matching the slot; these poses do
// exactly that, with small random tilts, on either side of the opening along its normal.
#pragma once

#include "opening_frame.hpp"
#include "scenario.hpp"

#include <ompl/util/RandomNumbers.h>

#include <Eigen/Geometry>

#include <vector>

namespace planner {

/// The robot's principal axes: eigenvectors of its surface's second moment (area-weighted,
/// exact per triangle; soups need no closing), ordered by the robot's extent along them,
/// longest first, as the columns of a rotation (right-handed). A robot turning about z only
/// (`planar`) gets its long axis in the xy-plane, the third axis z.
Eigen::Matrix3d robotPrincipalAxes(const acd::TriMesh& robot, bool planar);

class OpeningAlignment {
 public:
  /// `robot`: a box or mesh robot (its triangles in its own frame, reference point at the
  /// origin). `planar`: the robot turns about z only.
  OpeningAlignment(const Robot& robot, const std::vector<Opening>& openings, bool planar);

  const OpeningFrame& frame(int opening) const { return frames_[opening]; }
  const Eigen::Matrix3d& robotAxes() const { return axes_; }

  /// The robot's long axis along `longSign` x the opening's normal, its second axis along
  /// `crossSign` x the opening's long side (the third follows; a proper rotation). Planar:
  /// the rotation about z closest to that (long axis along the normal's horizontal part).
  Eigen::Matrix3d alignedRotation(int opening, int longSign, int crossSign) const;

  /// A random aligned pose at opening `opening`: one of the four sign variants, tilted by a
  /// random rotation whose angle components are normal with std. deviation `tilt` (radians;
  /// about z only when planar), placed so that the robot's extent across the opening lies
  /// within the opening's rectangle (uniform over the room left; centred when there is none),
  /// and with the middle of its extent along the normal at a normal deviate of std. deviation
  /// `spread` from the opening's plane.
  Pose sample(int opening, ompl::RNG& rng, double tilt, double spread) const;

 private:
  std::vector<acd::Vec3> vertices_;  // the robot's corners, reference point at the origin
  bool planar_;
  Eigen::Matrix3d axes_;
  std::vector<OpeningFrame> frames_;
};

}  // namespace planner
