#include "threading_poses.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace planner {

namespace {

/// Threadings of the parts of `parts` through the gaps of `gaps`.
void addThreadings(const BodyParts& gaps, const BodyParts& parts, bool gapInRobot, std::vector<Threading>& out) {
  for (int g = 0; g < static_cast<int>(gaps.gaps.size()); ++g)
    for (int p = 0; p < static_cast<int>(parts.parts.size()); ++p)
      for (int axis = 0; axis < 3; ++axis)
        if (2.0 * parts.parts[p].halfExtent[axis] < gaps.gaps[g].width) out.push_back({gapInRobot, g, p, axis});
}

/// The part's longest axis other than `axis`.
int slideAxis(int axis) { return axis == 0 ? 1 : 0; }

}  // namespace

ThreadingPoses::ThreadingPoses(BodyParts robot, BodyParts obstacles)
    : robot_(std::move(robot)), obstacles_(std::move(obstacles)) {
  addThreadings(obstacles_, robot_, false, threadings_);
  addThreadings(robot_, obstacles_, true, threadings_);
  double total = 0.0;
  for (const Threading& t : threadings_) {
    total += 1.0 / (t.gapInRobot ? robot_ : obstacles_).gaps[t.gap].width;
    cumulativeWeight_.push_back(total);
  }
}

Pose ThreadingPoses::sample(ompl::RNG& rng, double tilt) const {
  const double w = rng.uniformReal(0.0, cumulativeWeight_.back());
  const std::size_t which = std::min<std::size_t>(
      std::lower_bound(cumulativeWeight_.begin(), cumulativeWeight_.end(), w) - cumulativeWeight_.begin(),
      threadings_.size() - 1);
  const Threading& t = threadings_[which];
  const PartGap& gap = (t.gapInRobot ? robot_ : obstacles_).gaps[t.gap];
  const BodyPart& part = (t.gapInRobot ? obstacles_ : robot_).parts[t.part];
  const double sign = rng.uniformBool() ? 1.0 : -1.0;
  const double turn = rng.uniformReal(-M_PI, M_PI);
  const acd::Vec3 w3(rng.gaussian(0.0, tilt), rng.gaussian(0.0, tilt), rng.gaussian(0.0, tilt));
  const Eigen::Matrix3d tilted =
      w3.norm() > 0 ? Eigen::AngleAxisd(w3.norm(), w3.normalized()).toRotationMatrix() : Eigen::Matrix3d::Identity();
  const int slide = slideAxis(t.axis);
  const acd::Vec3 onPart =
      part.centre + rng.uniformReal(-part.halfExtent[slide], part.halfExtent[slide]) * part.axes.col(slide);
  const double jitter = 0.25 * gap.width;
  const acd::Vec3 shake(rng.gaussian(0.0, jitter), rng.gaussian(0.0, jitter), rng.gaussian(0.0, jitter));
  // The part's frame: its axis across the gap, its length (the slide axis) along the way through.
  Eigen::Matrix3d partFrame;
  partFrame.col(0) = part.axes.col(t.axis);
  partFrame.col(1) = part.axes.col(slide);
  partFrame.col(2) = partFrame.col(0).cross(partFrame.col(1));
  // The gap's frame: its direction, and the way through (or a uniform turn about the direction).
  Eigen::Matrix3d gapFrame;
  gapFrame.col(0) = sign * gap.direction;
  acd::Vec3 through = gap.through;
  if (through.isZero()) {
    through = gapFrame.col(0).unitOrthogonal();
    through = Eigen::AngleAxisd(turn, gapFrame.col(0)) * through;
  } else if (rng.uniformBool()) {
    through = -through;
  }
  gapFrame.col(1) = through;
  gapFrame.col(2) = gapFrame.col(0).cross(gapFrame.col(1));
  Pose pose;
  Eigen::Matrix3d R;
  if (!t.gapInRobot) {
    // The robot's part in the obstacles' gap: the part's frame onto the gap's.
    R = tilted * gapFrame * partFrame.transpose();
    pose.position = gap.middle + shake - R * onPart;
  } else {
    // The obstacle's part in the robot's gap: the robot's gap frame onto the part's.
    R = tilted * partFrame * gapFrame.transpose();
    pose.position = onPart + shake - R * gap.middle;
  }
  pose.orientation = Eigen::Quaterniond(R).normalized();
  return pose;
}

}  // namespace planner
