#include "scenes.hpp"

namespace scenes {

using acd::Vec3;

Scene twistyPassage() {
  Scene s;
  s.name = "twisty";
  // Wall 0.3 thick at x = 3.5; the slot is y in [0.85, 2.15], z in [1.3, 1.7]. The reference
  // point stays in [0,7] x [0,3] x [0,3] (the scenario's volume) but the robot reaches 1.46
  // beyond it, so the wall spans [-1.5, 4.5] in y and z. The four pieces overlap.
  const double x0 = 3.35, x1 = 3.65, lo = -1.5, hi = 4.5;
  s.environment.add("wall_left", doubleSided(boxSurface({x0, lo, lo}, {x1, 0.85, hi})));
  s.environment.add("wall_right", doubleSided(boxSurface({x0, 2.15, lo}, {x1, hi, hi})));
  s.environment.add("wall_below", doubleSided(boxSurface({x0, 0.5, lo}, {x1, 2.5, 1.3})));
  s.environment.add("wall_above", doubleSided(boxSurface({x0, 0.5, 1.7}, {x1, 2.5, hi})));
  // Robot frame: the shaft along x, centred on the origin (the reference point).
  s.robot.add("shaft", boxSurface({-1.0, -0.1, -0.1}, {1.0, 0.1, 0.1}));
  s.robot.add("crossbar", boxSurface({0.8, -0.5, -0.1}, {1.0, 0.5, 0.1}));
  return s;
}

Scene bugTrap() {
  Scene s;
  s.name = "bugtrap";
  // Trap [2,4] x [2,4] x [1,3] in the workspace [0,6] x [0,6] x [0,4]; the tube runs from the
  // +x wall (x = 4) inward to x = 3.2, cross-section y in [2.8, 3.2], z in [1.8, 2.2].
  const Vec3 lo(2, 2, 1), hi(4, 4, 3);
  s.environment.add("trap_walls", boxSides(lo, hi, {"+x"}));
  const double x = hi.x(), y0 = 2.8, y1 = 3.2, z0 = 1.8, z1 = 2.2;
  // The +x wall around the hole: four strips, facing +x.
  s.environment.add("front_below", quad({x, lo.y(), lo.z()}, {x, hi.y(), lo.z()}, {x, hi.y(), z0}, {x, lo.y(), z0}));
  s.environment.add("front_above", quad({x, lo.y(), z1}, {x, hi.y(), z1}, {x, hi.y(), hi.z()}, {x, lo.y(), hi.z()}));
  s.environment.add("front_left", quad({x, lo.y(), z0}, {x, y0, z0}, {x, y0, z1}, {x, lo.y(), z1}));
  s.environment.add("front_right", quad({x, y1, z0}, {x, hi.y(), z0}, {x, hi.y(), z1}, {x, y1, z1}));
  // The tube: four sides, open at both ends.
  s.environment.add("tube", boxSides({3.2, y0, z0}, {x, y1, z1}, {"-x", "+x"}));
  s.robot.add("rod", boxSurface({-0.35, -0.075, -0.075}, {0.35, 0.075, 0.075}));
  return s;
}

Scene clutteredRoom() {
  Scene s;
  s.name = "room";
  // Room [0,8] x [0,6] x [0,3].
  s.environment.add("table_top", doubleSided(boxSurface({2.5, 2.0, 0.70}, {4.5, 3.5, 0.78})));
  for (const auto& [x, y] : {std::pair{2.55, 2.05}, {4.35, 2.05}, {2.55, 3.35}, {4.35, 3.35}})
    s.environment.add("table_leg", doubleSided(boxSurface({x, y, 0.0}, {x + 0.1, y + 0.1, 0.75})));
  s.environment.add("shelf", boxSurface({0.5, 5.5, 0.0}, {2.5, 6.0, 2.2}));
  s.environment.add("cabinet", boxSurface({2.4, 5.4, 0.0}, {3.4, 6.0, 1.0}));
  s.environment.add("pillar", boxSurface({1.8, 1.0, 0.0}, {2.1, 1.3, 3.0}));
  s.environment.add("pillar", boxSurface({4.8, 4.2, 0.0}, {5.1, 4.5, 3.0}));
  s.environment.add("chair", doubleSided(boxSurface({3.0, 1.3, 0.0}, {3.5, 1.8, 0.45})));
  s.environment.add("chair_back", doubleSided(boxSurface({3.0, 1.2, 0.0}, {3.5, 1.35, 1.0})));
  s.environment.add("lamp", boxSurface({3.3, 2.6, 2.2}, {3.7, 3.0, 2.5}));  // hangs free: a cavity of the free space
  // Partition at x = 6 with a door y in [2.5, 3.5], z in [0, 2]: zero thickness, double-sided.
  const double x = 6.0;
  s.environment.add("partition", doubleSided(quad({x, 0, 0}, {x, 2.5, 0}, {x, 2.5, 3}, {x, 0, 3})));
  s.environment.add("partition", doubleSided(quad({x, 3.5, 0}, {x, 6, 0}, {x, 6, 3}, {x, 3.5, 3})));
  s.environment.add("partition", doubleSided(quad({x, 2.5, 2}, {x, 3.5, 2}, {x, 3.5, 3}, {x, 2.5, 3})));
  // An L: a 0.9 x 0.3 x 0.3 bar and a 0.3 x 0.6 x 0.3 foot, overlapping at one end.
  s.robot.add("bar", boxSurface({-0.45, -0.15, -0.15}, {0.45, 0.15, 0.15}));
  s.robot.add("foot", boxSurface({0.15, -0.15, -0.15}, {0.45, 0.45, 0.15}));
  return s;
}

std::vector<Scene> allScenes() { return {twistyPassage(), bugTrap(), clutteredRoom()}; }

}  // namespace scenes
