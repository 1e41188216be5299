#include "ompl_app_problems.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace scenes {

using acd::Vec3;

namespace {

acd::TriMesh moved(acd::TriMesh m, const Eigen::Affine3d& t) {
  for (Vec3& v : m.vertices) v = t * v;
  return m;
}

Eigen::Affine3d turn(double degrees, const Vec3& axis) {
  return Eigen::Affine3d(Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()));
}

/// A wall across x (x in [3.35, 3.65]) with a window y in [y0, y1], z in [z0, z1]; the wall
/// reaches from -2 to 5 in y and z. Four overlapping boxes, every face double-sided.
void wallWithWindow(Soup& env, double y0, double y1, double z0, double z1) {
  const double x0 = 3.35, x1 = 3.65, lo = -2.0, hi = 5.0;
  env.add("wall_left", doubleSided(boxSurface({x0, lo, lo}, {x1, y0, hi})));
  env.add("wall_right", doubleSided(boxSurface({x0, y1, lo}, {x1, hi, hi})));
  env.add("wall_below", doubleSided(boxSurface({x0, y0 - 0.1, lo}, {x1, y1 + 0.1, z0})));
  env.add("wall_above", doubleSided(boxSurface({x0, y0 - 0.1, z1}, {x1, y1 + 0.1, hi})));
}

/// A square ring in the xy-plane centred on the origin: outer side `outer`, bars `bar` wide
/// and thick; `gapAt` >= 0 leaves a gap of that width in the middle of the +y bar.
void squareRing(Soup& soup, const std::string& name, double outer, double bar, double gap, const Eigen::Affine3d& t) {
  const double o = outer / 2, i = o - bar, h = bar / 2;
  soup.add(name + "_left", moved(boxSurface({-o, -o, -h}, {-i, o, h}), t));
  soup.add(name + "_right", moved(boxSurface({i, -o, -h}, {o, o, h}), t));
  soup.add(name + "_bottom", moved(boxSurface({-o, -o, -h}, {o, -i, h}), t));
  if (gap <= 0) {
    soup.add(name + "_top", moved(boxSurface({-o, i, -h}, {o, o, h}), t));
  } else {
    soup.add(name + "_top_a", moved(boxSurface({-o, i, -h}, {-gap / 2, o, h}), t));
    soup.add(name + "_top_b", moved(boxSurface({gap / 2, i, -h}, {o, o, h}), t));
  }
}

struct Cfg {
  std::ostringstream s;
  explicit Cfg(const std::string& name) { s << std::setprecision(10) << "[problem]\nname=" << name << "\nworld=" << name << "_env.dae\nrobot=" << name << "_robot.dae\n"; }
  void se3(const std::string& which, const Vec3& p, const Vec3& axis, double theta) {
    s << which << ".x=" << p.x() << "\n" << which << ".y=" << p.y() << "\n" << which << ".z=" << p.z() << "\n"
      << which << ".axis.x=" << axis.x() << "\n" << which << ".axis.y=" << axis.y() << "\n" << which << ".axis.z=" << axis.z()
      << "\n" << which << ".theta=" << theta << "\n";
  }
  void volume(const Vec3& lo, const Vec3& hi) {
    s << "volume.min.x=" << lo.x() << "\nvolume.min.y=" << lo.y() << "\nvolume.min.z=" << lo.z() << "\nvolume.max.x=" << hi.x()
      << "\nvolume.max.y=" << hi.y() << "\nvolume.max.z=" << hi.z() << "\n";
  }
  void benchmark(double limit, int runs) { s << "\n[benchmark]\ntime_limit=" << limit << "\nrun_count=" << runs << "\n"; }
  std::string text() const { return s.str(); }
};

const double kHalfTurn = M_PI / 2;

/// The problem of the robots that pass a window in the wall at x = 3.5: from (1.5, 1.5, 1.5),
/// turned by `theta` about `axis`, to (5.5, 1.5, 1.5) unturned; the reference point in
/// [0, 7] x [0, 3] x [0, 3]; 10 runs of 10 s.
std::string throughTheWall(const std::string& name, const Vec3& axis, double theta) {
  Cfg c(name);
  c.se3("start", {1.5, 1.5, 1.5}, axis, theta);
  c.se3("goal", {5.5, 1.5, 1.5}, {0, 0, 1}, 0);
  c.volume({0, 0, 0}, {7, 3, 3});
  c.benchmark(10, 10);
  return c.text();
}

OmplAppProblem lRobot() {
  OmplAppProblem p;
  p.what = "an L-shaped robot drawn with its corner at the origin: its reference point (the vertices' mean) lies outside it";
  p.scene.name = "l_robot";
  wallWithWindow(p.scene.environment, 0.9, 2.1, 1.25, 1.75);
  p.scene.robot.add("bar", boxSurface({0, 0, 0}, {1.2, 0.2, 0.2}));
  p.scene.robot.add("foot", boxSurface({0, 0, 0}, {0.2, 0.8, 0.2}));
  p.cfg = throughTheWall(p.scene.name, {1, 0, 0}, kHalfTurn);  // the foot upright: it must lie down to pass
  return p;
}

OmplAppProblem ringRobot() {
  OmplAppProblem p;
  p.what = "a square ring robot: its reference point is the middle of its hole";
  p.scene.name = "ring_robot";
  wallWithWindow(p.scene.environment, 0.8, 2.2, 1.25, 1.75);  // 0.2 to spare across the ring, lying flat
  squareRing(p.scene.robot, "ring", 1.0, 0.15, 0, turn(90, Vec3::UnitY()));  // drawn upright (in the yz-plane)
  p.cfg = throughTheWall(p.scene.name, {0, 0, 1}, 0);  // drawn upright: it must lie down to pass
  return p;
}

OmplAppProblem twoBarRobot() {
  OmplAppProblem p;
  p.what = "two bars joined at 60 degrees (a V): the reference point lies between the arms, outside the robot";
  p.scene.name = "two_bar_robot";
  wallWithWindow(p.scene.environment, 0.9, 2.1, 1.3, 1.7);
  p.scene.robot.add("arm_a", moved(boxSurface({0, -0.075, -0.075}, {1.0, 0.075, 0.075}), turn(30, Vec3::UnitZ())));
  p.scene.robot.add("arm_b", moved(boxSurface({0, -0.075, -0.075}, {1.0, 0.075, 0.075}), turn(-30, Vec3::UnitZ())));
  p.cfg = throughTheWall(p.scene.name, {1, 0, 0}, kHalfTurn);  // the V upright: it must lie down to pass
  return p;
}

OmplAppProblem farWorld() {
  OmplAppProblem p;
  p.what = "world and robot in world coordinates far from the origin (the robot drawn where it starts), no volume";
  p.scene.name = "far_world";
  const Eigen::Affine3d far(Eigen::Translation3d(1000, -2000, 500));
  Soup env;
  wallWithWindow(env, 0.9, 2.1, 1.2, 1.8);
  for (std::size_t i = 0; i < env.pieces.size(); ++i) p.scene.environment.add(env.names[i], moved(env.pieces[i], far));
  // The floor and the ceiling of the scene bound it (OMPL.app infers the volume from them).
  p.scene.environment.add("floor", moved(boxSurface({-1, -2, -2.2}, {8, 5, -2}), far));
  const Eigen::Affine3d at = far * Eigen::Translation3d(1.5, 1.5, 1.5);
  p.scene.robot.add("rod", moved(boxSurface({-0.5, -0.1, -0.1}, {0.5, 0.1, 0.1}), at));
  Cfg c(p.scene.name);
  c.se3("start", {1001.5, -1998.5, 501.5}, {0, 0, 1}, 0);
  c.se3("goal", {1005.5, -1998.5, 501.5}, {0, 0, 1}, 0);
  c.benchmark(10, 10);
  p.cfg = c.text();
  return p;
}

OmplAppProblem bugTrapProblem() {
  OmplAppProblem p;
  p.what = "a bug trap: the robot starts inside a nearly closed box whose only exit is a narrow inward tube";
  p.scene = bugTrap();
  p.scene.name = "bug_trap";
  Cfg c(p.scene.name);
  c.se3("start", {2.6, 3.0, 2.0}, {0, 0, 1}, 0);
  c.se3("goal", {5.3, 5.0, 2.0}, {0, 0, 1}, 0);
  c.volume({0, 0, 0}, {6, 6, 4});
  c.benchmark(30, 10);
  p.cfg = c.text();
  return p;
}

OmplAppProblem plannerList() {
  OmplAppProblem p = lRobot();
  p.what = "a [planner] section with repeated keys (one line per planner instance) and parameters";
  p.scene.name = "planner_list";
  p.cfg = throughTheWall(p.scene.name, {1, 0, 0}, kHalfTurn) + "\n[planner]\nrrtconnect=\nrrtconnect=\nrrtconnect.range=0.5\nkpiece=\nsbl=\naps=\n";
  return p;
}

OmplAppProblem se2Slot() {
  OmplAppProblem p;
  p.what = "an SE(2) problem (start.x, start.y, start.theta only): a flat bar turns about z to pass a slot";
  p.scene.name = "se2_slot";
  // Walls of height [-0.5, 0.5] across x = 3 with a slot y in [1.3, 1.7].
  p.scene.environment.add("wall_a", doubleSided(boxSurface({2.8, -0.5, -0.5}, {3.2, 1.3, 0.5})));
  p.scene.environment.add("wall_b", doubleSided(boxSurface({2.8, 1.7, -0.5}, {3.2, 3.5, 0.5})));
  p.scene.robot.add("bar", boxSurface({-0.6, -0.1, -0.1}, {0.6, 0.1, 0.1}));
  std::ostringstream s;
  s << "[problem]\nname=se2_slot\nworld=se2_slot_env.dae\nrobot=se2_slot_robot.dae\n"
    << "start.x=1\nstart.y=1.5\nstart.theta=1.5707963\ngoal.x=5\ngoal.y=1.5\ngoal.theta=0\n"
    << "volume.min.x=0\nvolume.min.y=0\nvolume.max.x=6\nvolume.max.y=3\n\n[benchmark]\ntime_limit=10\nrun_count=10\n";
  p.cfg = s.str();
  return p;
}

OmplAppProblem twistyCfg() {
  OmplAppProblem p;
  p.what = "the twisty passage of scenarios/twisty.yaml as an OMPL.app problem file";
  p.scene = twistyPassage();
  p.scene.name = "twisty_cfg";
  Cfg c(p.scene.name);
  c.se3("start", {1.5, 1.5, 1.5}, {0, 1, 0}, -kHalfTurn);
  c.se3("goal", {5.5, 1.5, 1.5}, {0, 0, 1}, kHalfTurn);
  c.volume({0, 0, 0}, {7, 3, 3});
  c.benchmark(30, 10);
  p.cfg = c.text();
  return p;
}

OmplAppProblem alphaLinks() {
  OmplAppProblem p;
  p.what = "two interlocked square links (in the manner of the alpha puzzle): the robot link must slide round the fixed "
           "one to a 0.3 gap in it and pass its 0.2 bar through";
  p.scene.name = "alpha_links";
  // The fixed link stands in the xz-plane (outer 2.0, bars 0.2), its gap in the middle of the top bar.
  squareRing(p.scene.environment, "fixed", 2.0, 0.2, 0.3, turn(90, Vec3::UnitX()));
  // The robot link lies in the xy-plane (outer 1.4, bars 0.2), hooked round the fixed link's right bar.
  squareRing(p.scene.robot, "link", 1.4, 0.2, 0, Eigen::Affine3d(Eigen::Translation3d(1.0, 0, 0)));
  Cfg c(p.scene.name);
  c.se3("start", {1.0, 0, 0}, {0, 0, 1}, 0);
  c.se3("goal", {0, 2.5, 0}, {0, 0, 1}, 0);
  c.volume({-3, -3, -3}, {3, 3, 3});
  c.benchmark(60, 10);
  p.cfg = c.text();
  return p;
}

}  // namespace

std::vector<OmplAppProblem> omplAppProblems() {
  return {lRobot(), ringRobot(), twoBarRobot(), farWorld(), bugTrapProblem(), plannerList(), se2Slot(), twistyCfg(),
          alphaLinks()};
}

}  // namespace scenes
