// OMPL.app's problem files (.cfg), read as OMPL.app reads them (its benchmark program and
// RigidBodyGeometry; docs/PLANNER.md, "OMPL.app problems"):
//   [problem]  world, robot: meshes, paths relative to the .cfg;
//              start.x/y/z + start.axis.x/y/z + start.theta (SE(3), axis-angle in radians),
//              or start.x/y + start.theta alone (SE(2): the robot turns about z at z = 0);
//              goal.* alike; volume.min.* / volume.max.*: bounds of the reference point only
//              (default: the box of the environment's vertices and the start and goal);
//   [benchmark] time_limit, run_count;  [planner] one line per planner instance (repeats
//              kept), `name.param=value` for its parameters.
// The robot's reference point is OMPL.app's (robot_center.hpp); validity is OMPL.app's rule
// (Validity::Triangles): the robot touches none of the environment's triangles.
#pragma once

#include "scenario.hpp"

#include <string>

namespace planner {

/// The file's name ends in .cfg.
bool isOmplAppProblem(const std::string& path);

/// The problem as a scenario (samplers, counts and seed at their defaults).
/// \throw ScenarioError naming the file and the key (missing, not a number, unreadable mesh).
Scenario loadOmplAppProblem(const std::string& path);

/// The same from the file's text; `baseDir` resolves the mesh paths.
Scenario parseOmplAppProblem(const std::string& text, const std::string& sourceName, const std::string& baseDir);

}  // namespace planner
