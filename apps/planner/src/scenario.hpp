// Motion-planning scenarios: the YAML format documented in docs/PLANNER.md.
#pragma once

#include "solid_obstacles.hpp"

#include <acd/mesh.hpp>

#include <Eigen/Geometry>

#include <stdexcept>
#include <string>
#include <vector>

namespace planner {

/// Bad scenario: the message names the file and the offending key, file or pose.
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Pose {
  acd::Vec3 position = acd::Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

enum class RobotKind { Point, Sphere, Box, Mesh };

struct Robot {
  RobotKind kind = RobotKind::Point;
  double radius = 0.0;                         // sphere
  acd::Vec3 size = acd::Vec3::Zero();          // box: full edge lengths, centred on the reference point
  acd::TriMesh mesh;                           // box and mesh: the triangles (any soup), in the robot's frame
  acd::TriMesh solid;                          // closed pieces covering `mesh` (point location); empty: `mesh` is closed
  std::string solidSummary;                    // mesh: how the solid was made (solid_obstacles.hpp)
  std::string meshPath;                        // mesh
  bool planar = false;                         // SE(2): moves in the xy-plane at the start's z, turns about z
  /// Points strictly inside the robot, one per closed piece, in its frame (inside_points.hpp);
  /// the first is the robot's body point for the samplers. The reference point (the frame's
  /// origin) may lie anywhere, inside the robot or not.
  std::vector<acd::Vec3> insidePoints{acd::Vec3::Zero()};
  /// Largest distance from the reference point to the robot's surface.
  double boundingRadius() const;
  /// Smallest extent of the robot's bounding box (2 radius for a sphere, 0 for a point): no
  /// passage narrower than this matters, so the obstacles' wrap may close it.
  double thickness() const;
  /// The closed robot for point location.
  const acd::TriMesh& closedMesh() const { return solid.empty() ? mesh : solid; }
};

/// An obstacle as given: the triangles the robot must not touch (closed or not).
struct Obstacle {
  std::string name;             // "obstacles[0] (box)", "world (env.dae)"...
  acd::TriMesh triangles;
  bool box = false;             // an axis-aligned box: closed as it is
};

/// What makes a pose valid. `FreeSpace`: the robot touches none of the obstacles' triangles
/// (nor the workspace's walls) and lies in the free space (its inside points in the free
/// space's solid, no obstacle piece inside it). `Triangles`: OMPL.app's rule, the robot
/// touches none of the environment's triangles (a robot wholly inside a closed obstacle is
/// valid there too). Either way the reference point stays within `volume`.
enum class Validity { FreeSpace, Triangles };

struct PrmSettings {
  int neighbors = 10;             // k of the k-nearest connection strategy
  double resolution = 0.002;      // motion checking step, fraction of the space's maximum extent
};

struct AcdSamplerSettings {
  double tau = 0.05;              // concavity tolerance of the free-space ACD (normalised units)
  double spread = -1.0;           // std. deviation across the opening, length units; < 0: half the robot's bounding radius
  double uniformFraction = 0.1;   // share of plain uniform samples mixed in
  int orientationTries = 20;      // random orientations tried at one free position
  double alignedFraction = 0.5;   // share of the opening samples posed aligned to the opening (turning robots)
  double tilt = 0.1;              // std. deviation of the aligned poses' random tilt, radians
  double threadFraction = 0.5;    // share of the non-uniform samples that thread a part through a gap (threading_poses.hpp)
};

/// One planner of the race (--race), as OMPL.app's [planner] section names it ("rrtconnect",
/// "kpiece"...), with its parameters ("range" -> "0.5"); a name may come more than once.
struct PlannerEntry {
  std::string name;
  std::vector<std::pair<std::string, std::string>> params;
};

/// The race against OMPL's planners: OMPL.app's [benchmark] time_limit and run_count, and the
/// planners its [planner] section lists (raced besides the standard set, ompl_planners.hpp).
struct RaceSettings {
  double timeLimit = 30.0;
  int runs = 20;
  std::vector<PlannerEntry> planners;
};

struct Scenario {
  std::string path;               // the YAML file
  std::string name;
  std::string description;
  std::string expected;           // the documented expected outcome
  acd::Box3 workspace;            // the robot stays inside this box (its walls are obstacles)
  acd::Box3 bounds;               // where the reference point may go (OMPL.app's `volume`); default: the workspace
  std::vector<Obstacle> obstacles;
  WrapSettings wrap{-1.0, -1.0};  // < 0: from the robot's thickness (resolvedWrap)
  acd::TriMesh freeSpace;         // given directly (then `obstacles` is empty)
  bool freeSpaceGiven = false;
  Robot robot;
  Pose start, goal;
  Validity validity = Validity::FreeSpace;
  RaceSettings race;
  std::vector<std::string> samplers{"uniform", "acd", "gaussian", "obstacle_based", "bridge_test"};  // of knownSamplers()
  int samples = 200;
  int trials = 100;
  std::vector<int> sweep{50, 100, 200, 300, 500, 750, 1000};  // sample counts for the plot
  int sweepTrials = 30;
  PrmSettings prm;
  AcdSamplerSettings acd;
  unsigned seed = 1;
  std::string outputDir;          // relative paths resolve against the current directory
};

/// Wrap settings for the obstacles: as given, else alpha = thickness / 2 and offset =
/// thickness / 40 of the robot (a point robot: 1 % and 0.05 % of the workspace diagonal).
WrapSettings resolvedWrap(const Scenario& scenario);

/// The known sampler names, in their canonical order.
const std::vector<std::string>& knownSamplers();

/// Parses and validates a scenario file; mesh paths resolve relative to the file.
/// \throw ScenarioError naming the problem (wrong key, missing file, bad value...).
Scenario loadScenario(const std::string& path);

/// Parses a scenario from YAML text; `baseDir` resolves relative mesh paths.
Scenario parseScenario(const std::string& yamlText, const std::string& sourceName, const std::string& baseDir);

}  // namespace planner
