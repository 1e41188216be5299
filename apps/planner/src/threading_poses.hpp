// Poses that thread a part of one body through a gap of the other (body_parts.hpp): the
// robot's bar through a gap in an obstacle, or an obstacle's bar through the robot's hole.
// These are the passages of the configuration space that the free space's openings miss: the
// free space around two interlocked links is wide open, yet the moving link has a thin set of
// poses in which it can slide along the other or slip through its gap. A part fits a gap when
// one of its widths is below the gap's width; it is posed with that width across the gap,
// turned at random about the gap's direction, slid at random along its own length.
#pragma once

#include "body_parts.hpp"
#include "scenario.hpp"

#include <ompl/util/RandomNumbers.h>

#include <vector>

namespace planner {

/// A part of one body that fits a gap of the other, along one of its axes.
struct Threading {
  bool gapInRobot = false;   // the gap is the robot's and the part an obstacle's; else the reverse
  int gap = 0, part = 0;
  int axis = 0;              // the part's axis laid across the gap
};

class ThreadingPoses {
 public:
  /// `robot`: the robot's parts and gaps in its own frame (reference point at the origin);
  /// `obstacles`: the obstacles' in the world.
  ThreadingPoses(BodyParts robot, BodyParts obstacles);

  const std::vector<Threading>& threadings() const { return threadings_; }
  const BodyParts& robot() const { return robot_; }
  const BodyParts& obstacles() const { return obstacles_; }

  /// A random threading pose: a threading chosen with probability proportional to 1 / its gap's
  /// width (narrow gaps first), the part's axis along the gap's direction (either sign), a
  /// uniform turn about it, then a random rotation whose angle components are normal with std.
  /// deviation `tilt` (radians); the part's centre slid uniformly along its longest other axis
  /// within its length and put at the gap's middle, moved by a normal deviate of std. deviation
  /// a quarter of the gap's width in each direction.
  Pose sample(ompl::RNG& rng, double tilt) const;

 private:
  BodyParts robot_, obstacles_;
  std::vector<Threading> threadings_;
  std::vector<double> cumulativeWeight_;
};

}  // namespace planner
