// The planner's benchmark scenes, made here rather than taken from third parties: each is an
// environment and a robot, both polygon soups (docs/PLANNER.md, "Soup scenes").
#pragma once

#include "soup.hpp"

#include <string>
#include <vector>

namespace scenes {

struct Scene {
  std::string name;   // files <name>_env.dae and <name>_robot.dae
  Soup environment;
  Soup robot;
};

/// A wall with a slot 1.3 x 0.4 (four overlapping boxes, every face double-sided) and a
/// T-shaped robot (a 2.0 x 0.2 x 0.2 shaft with a 1.0 crossbar at one end, two overlapping
/// boxes) that must turn shaft-first or crossbar-first to pass.
Scene twistyPassage();

/// A hollow box floating above the floor, walls of zero thickness (open, single-sided
/// quads), entered only through a 0.4 x 0.4 tube pointing inward; a rod starts inside.
Scene bugTrap();

/// A room with a table, shelves, pillars, a hanging lamp (floating) and a partition with a
/// door (zero-thickness, double-sided); an L-shaped robot.
Scene clutteredRoom();

std::vector<Scene> allScenes();

}  // namespace scenes
