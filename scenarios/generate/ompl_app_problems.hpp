// Planning problems written in OMPL.app's own format (a .cfg problem file beside COLLADA meshes
// from the project's exporter), one per convention of that format the planner must follow
// (docs/PLANNER.md, "OMPL.app problems"), and narrow-passage puzzles for the race.
#pragma once

#include "scenes.hpp"

#include <string>
#include <vector>

namespace scenes {

struct OmplAppProblem {
  Scene scene;        // written as <name>_env.dae and <name>_robot.dae
  std::string cfg;    // the text of <name>.cfg
  std::string what;   // the convention it pins, one line
};

/// l_robot, ring_robot, two_bar_robot (reference points outside the robot), far_world (meshes
/// in world coordinates far from the origin), bug_trap (start inside a trap), planner_list
/// (repeated [planner] keys), se2_slot (an SE(2) problem), twisty_cfg and alpha_links (the
/// race's narrow passages).
std::vector<OmplAppProblem> omplAppProblems();

}  // namespace scenes
