#include "scenario.hpp"

#include "inside_points.hpp"
#include "ompl_app_import.hpp"

#include <acd/diagnosis.hpp>
#include <acd/algo/inside.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>
#include <sandbox/scene_reader.hpp>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace planner {

const std::vector<std::string>& knownSamplers() {
  static const std::vector<std::string> names{"uniform", "acd", "gaussian", "obstacle_based", "bridge_test",
                                              "max_clearance"};
  return names;
}

double Robot::boundingRadius() const {
  switch (kind) {
    case RobotKind::Point: return 0.0;
    case RobotKind::Sphere: return radius;
    case RobotKind::Box:
    case RobotKind::Mesh: {
      double r = 0.0;
      for (const acd::Vec3& p : mesh.vertices) r = std::max(r, p.norm());
      return r;
    }
  }
  return 0.0;
}

double Robot::thickness() const {
  switch (kind) {
    case RobotKind::Point: return 0.0;
    case RobotKind::Sphere: return 2 * radius;
    case RobotKind::Box:
    case RobotKind::Mesh: return acd::boundingBox(closedMesh()).size().minCoeff();
  }
  return 0.0;
}

WrapSettings resolvedWrap(const Scenario& scenario) {
  double t = scenario.robot.thickness();
  if (t <= 0) t = 0.02 * scenario.workspace.size().norm();
  // With validity by the triangles alone the wrap only steers the acd sampler, so it may be
  // coarser: a passage narrower than the robot's thickness is one it cannot take anyway.
  const bool steersOnly = scenario.validity == Validity::Triangles;
  WrapSettings w;
  w.alpha = scenario.wrap.alpha > 0 ? scenario.wrap.alpha : steersOnly ? t : t / 2;
  w.offset = scenario.wrap.offset > 0 ? scenario.wrap.offset : steersOnly ? t / 20 : t / 40;
  return w;
}

namespace {

/// Reads one scenario: every error names the file and the key path ("robot.size").
class Parser {
 public:
  Parser(std::string source, std::string baseDir) : source_(std::move(source)), baseDir_(std::move(baseDir)) {}

  // frame: ompl_app: mesh files in OMPL.app's frame (COLLADA's up axis and unit applied).
  bool omplAppFrame_ = false;

  [[noreturn]] void fail(const std::string& what) const { throw ScenarioError(source_ + ": " + what); }

  void checkKeys(const YAML::Node& node, const std::string& where, const std::set<std::string>& allowed) const {
    if (!node.IsMap()) fail((where.empty() ? std::string("the document") : "'" + where + "'") + " must be a mapping");
    for (const auto& kv : node) {
      const std::string key = kv.first.as<std::string>();
      if (!allowed.count(key)) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail("unknown key '" + (where.empty() ? key : where + "." + key) + "' (allowed: " + list + ")");
      }
    }
  }

  template <class T>
  T scalar(const YAML::Node& node, const std::string& where) const {
    if (!node.IsScalar()) fail("'" + where + "' must be a single value");
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      fail("'" + where + "' has a value of the wrong type: '" + node.as<std::string>() + "'");
    }
  }

  double finite(const YAML::Node& node, const std::string& where) const {
    const double v = scalar<double>(node, where);
    if (!std::isfinite(v)) fail("'" + where + "' is not a finite number");
    return v;
  }

  double positive(const YAML::Node& node, const std::string& where) const {
    const double v = finite(node, where);
    if (v <= 0) fail("'" + where + "' must be positive");
    return v;
  }

  int positiveInt(const YAML::Node& node, const std::string& where) const {
    const int v = scalar<int>(node, where);
    if (v <= 0) fail("'" + where + "' must be a positive integer");
    return v;
  }

  acd::Vec3 vec3(const YAML::Node& node, const std::string& where) const {
    if (!node.IsSequence() || node.size() != 3) fail("'" + where + "' must be a list of three numbers");
    return {finite(node[0], where + "[0]"), finite(node[1], where + "[1]"), finite(node[2], where + "[2]")};
  }

  acd::Box3 box(const YAML::Node& node, const std::string& where) const {
    checkKeys(node, where, {"min", "max"});
    if (!node["min"] || !node["max"]) fail("'" + where + "' needs 'min' and 'max'");
    acd::Box3 b{vec3(node["min"], where + ".min"), vec3(node["max"], where + ".max")};
    if (!((b.hi - b.lo).array() > 0).all()) fail("'" + where + "' is empty: max must exceed min on every axis");
    return b;
  }

  std::string resolve(const std::string& file) const {
    std::filesystem::path p(file);
    if (p.is_relative() && !baseDir_.empty()) p = std::filesystem::path(baseDir_) / p;
    return p.lexically_normal().string();
  }

  /// The triangles of a mesh file (OFF/OBJ/PLY/STL, or a scene through assimp), as they are.
  /// Scene files are read as the acd command reads them, in a child process under a memory
  /// and a time cap: a file on which assimp crashes or runs away is a refusal, not an abort.
  acd::TriMesh meshFile(const YAML::Node& node, const std::string& where) const {
    const std::string file = resolve(scalar<std::string>(node, where));
    if (!std::filesystem::exists(file)) fail("'" + where + "': " + file + ": file not found");
    acd::ReadResult read = acdsandbox::readModel(file);
    if (!read.status.ok()) fail("'" + where + "': " + read.status.message);
    if (omplAppFrame_) {  // the sandbox said the file is safe to read; now read it as OMPL.app does
      std::optional<OmplAppImport> imported = importAsOmplApp(file, true);
      if (!imported) fail("'" + where + "': " + file + ": assimp finds no triangles in it");
      return std::move(imported->triangles);
    }
    return std::move(read.mesh);
  }

  /// A free space given as a file: it must be closed (it is decomposed and located in as it is).
  acd::TriMesh closedFile(const YAML::Node& node, const std::string& where) const {
    const std::string file = resolve(scalar<std::string>(node, where));
    const acd::PreparedSolid solid = acd::prepareSolid(meshFile(node, where));
    if (!solid.status.ok()) fail("'" + where + "': " + file + " is not a closed solid: " + solid.status.message);
    return acd::concatenate(solid.components);
  }

  acd::TriMesh transformed(acd::TriMesh m, const YAML::Node& node, const std::string& where) const {
    double scale = 1.0;
    acd::Vec3 shift = acd::Vec3::Zero();
    if (node["scale"]) scale = positive(node["scale"], where + ".scale");
    if (node["translate"]) shift = vec3(node["translate"], where + ".translate");
    for (acd::Vec3& p : m.vertices) p = scale * p + shift;
    return m;
  }

  Pose pose(const YAML::Node& node, const std::string& where) const {
    checkKeys(node, where, {"position", "orientation", "yaw_deg", "axis", "theta"});
    if (!node["position"]) fail("'" + where + "' needs 'position'");
    Pose p;
    p.position = vec3(node["position"], where + ".position");
    if ((node["orientation"] ? 1 : 0) + (node["yaw_deg"] ? 1 : 0) + (node["axis"] || node["theta"] ? 1 : 0) > 1)
      fail("'" + where + "': give one of 'orientation', 'yaw_deg' or 'axis' with 'theta'");
    if (node["axis"] || node["theta"]) {  // OMPL.app: a rotation of theta radians about axis
      if (!node["axis"] || !node["theta"]) fail("'" + where + "': 'axis' and 'theta' go together");
      const acd::Vec3 axis = vec3(node["axis"], where + ".axis");
      const double theta = finite(node["theta"], where + ".theta");
      // OMPL.app (SO3StateSpace::setAxisAngle) takes a zero axis as no rotation.
      if (axis.norm() > 0) p.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(theta, axis.normalized()));
    }
    if (node["orientation"]) {
      const YAML::Node& q = node["orientation"];
      if (!q.IsSequence() || q.size() != 4) fail("'" + where + ".orientation' must be a quaternion [w, x, y, z]");
      Eigen::Quaterniond quat(finite(q[0], where + ".orientation[0]"), finite(q[1], where + ".orientation[1]"),
                              finite(q[2], where + ".orientation[2]"), finite(q[3], where + ".orientation[3]"));
      if (quat.norm() < 1e-9) fail("'" + where + ".orientation' is not a rotation (zero quaternion)");
      p.orientation = quat.normalized();
    }
    if (node["yaw_deg"]) {
      const double yaw = finite(node["yaw_deg"], where + ".yaw_deg") * M_PI / 180.0;
      p.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, acd::Vec3::UnitZ()));
    }
    return p;
  }

  Robot robot(const YAML::Node& given) const {
    // OMPL.app's `robot=FILE`: a mesh robot whose reference point is the mean of its vertices.
    YAML::Node shorthand(YAML::NodeType::Map);
    if (given.IsScalar()) {
      shorthand["type"] = "mesh";
      shorthand["mesh"] = given.as<std::string>();
      shorthand["center"] = true;
    }
    const YAML::Node& node = given.IsScalar() ? shorthand : given;
    checkKeys(node, "robot", {"type", "radius", "size", "mesh", "scale", "translate", "center", "planar"});
    if (!node["type"]) fail("'robot' needs 'type' (point, sphere, box or mesh)");
    const std::string type = scalar<std::string>(node["type"], "robot.type");
    Robot r;
    auto forbid = [&](const char* key) {
      if (node[key]) fail("'robot." + std::string(key) + "' does not apply to a robot of type " + type);
    };
    if (type == "point") {
      r.kind = RobotKind::Point;
      forbid("radius"), forbid("size"), forbid("mesh");
    } else if (type == "sphere") {
      r.kind = RobotKind::Sphere;
      forbid("size"), forbid("mesh");
      if (!node["radius"]) fail("'robot' of type sphere needs 'radius'");
      r.radius = positive(node["radius"], "robot.radius");
    } else if (type == "box") {
      r.kind = RobotKind::Box;
      forbid("radius"), forbid("mesh");
      if (!node["size"]) fail("'robot' of type box needs 'size' [x, y, z]");
      r.size = vec3(node["size"], "robot.size");
      if (!(r.size.array() > 0).all()) fail("'robot.size' must be positive on every axis");
      r.mesh = acd::shapes::box(-0.5 * r.size, 0.5 * r.size);
    } else if (type == "mesh") {
      r.kind = RobotKind::Mesh;
      forbid("radius"), forbid("size");
      if (!node["mesh"]) fail("'robot' of type mesh needs 'mesh' (a file)");
      r.meshPath = resolve(scalar<std::string>(node["mesh"], "robot.mesh"));
      acd::TriMesh triangles = meshFile(node["mesh"], "robot.mesh");
      if (node["center"] && scalar<bool>(node["center"], "robot.center")) {
        if (node["translate"]) fail("'robot.center' and 'robot.translate' exclude each other");
        // OMPL.app's reference point (robot_center.hpp); an SE(2) robot keeps its heights.
        const std::optional<OmplAppImport> imported = importAsOmplApp(r.meshPath, omplAppFrame_);
        if (!imported) fail("'robot.mesh': " + r.meshPath + ": assimp finds no vertices to centre the robot on");
        std::optional<acd::Vec3> c = imported->center;
        if (node["planar"] && scalar<bool>(node["planar"], "robot.planar")) c->z() = 0.0;
        for (acd::Vec3& v : triangles.vertices) v -= *c;
      }
      r.mesh = transformed(std::move(triangles), node, "robot");
      // Point location needs a closed robot; a soup is closed by repair or a thin wrap.
      // The wrap's scale: the robot's thickness, or 1 % of its length for a flat robot.
      const acd::Vec3 extent = acd::boundingBox(r.mesh).size();
      const double size = std::max(extent.minCoeff(), 0.01 * extent.maxCoeff());
      if (!(size > 0)) fail("'robot.mesh': " + r.meshPath + " has no extent");
      const SolidObstacle solid = solidify(r.mesh, {size / 4, size / 100});
      if (!solid.ok || solid.pieces.empty()) fail("'robot.mesh': " + r.meshPath + ": cannot be made a closed solid: " + solid.error);
      r.solid = concatenatedPieces(solid);
      r.solidSummary = solid.summary();
      r.insidePoints = insidePoints(solid.pieces, acd::Vec3::Zero());
      if (r.insidePoints.empty()) fail("'robot.mesh': " + r.meshPath + " encloses no volume");
    } else {
      fail("'robot.type' must be point, sphere, box or mesh, not '" + type + "'");
    }
    if (r.kind != RobotKind::Mesh && (node["scale"] || node["translate"] || node["center"]))
      fail("'robot.scale', 'robot.translate' and 'robot.center' apply to mesh robots only");
    if (node["planar"]) r.planar = scalar<bool>(node["planar"], "robot.planar");
    if (r.planar && (r.kind == RobotKind::Point || r.kind == RobotKind::Sphere))
      fail("'robot.planar' needs an oriented robot (box or mesh)");
    return r;
  }

  Scenario scenario(const YAML::Node& root) {
    if (!root || root.IsNull()) fail("empty scenario");
    checkKeys(root, "", {"name", "description", "expected", "workspace", "volume", "world", "obstacles", "free_space",
                         "wrap", "robot", "start", "goal", "samplers", "samples", "trials", "sweep", "sweep_trials",
                         "prm", "acd", "seed", "output", "validity", "frame"});
    if (root["frame"]) {
      const std::string f = scalar<std::string>(root["frame"], "frame");
      if (f != "as_written" && f != "ompl_app") fail("'frame' must be as_written or ompl_app, not '" + f + "'");
      omplAppFrame_ = f == "ompl_app";
    }
    Scenario s;
    if (root["name"]) s.name = scalar<std::string>(root["name"], "name");
    if (root["description"]) s.description = scalar<std::string>(root["description"], "description");
    if (root["expected"]) s.expected = scalar<std::string>(root["expected"], "expected");
    readObstacles(root, s);
    if (root["validity"]) {
      const std::string v = scalar<std::string>(root["validity"], "validity");
      if (v == "free_space") s.validity = Validity::FreeSpace;
      else if (v == "triangles") s.validity = Validity::Triangles;
      else fail("'validity' must be free_space or triangles, not '" + v + "'");
    }
    if (!root["robot"]) fail("missing key 'robot'");
    s.robot = robot(root["robot"]);
    readSpace(root, s);
    if (root["wrap"]) {
      const YAML::Node& n = root["wrap"];
      checkKeys(n, "wrap", {"alpha", "offset"});
      if (n["alpha"]) s.wrap.alpha = positive(n["alpha"], "wrap.alpha");
      if (n["offset"]) s.wrap.offset = positive(n["offset"], "wrap.offset");
    }
    if (!root["start"]) fail("missing key 'start'");
    if (!root["goal"]) fail("missing key 'goal'");
    s.start = pose(root["start"], "start");
    s.goal = pose(root["goal"], "goal");
    if (s.robot.planar) {
      for (const Pose* p : {&s.start, &s.goal}) {
        const acd::Vec3 axis = p->orientation * acd::Vec3::UnitZ();
        if (axis.z() < 1 - 1e-9) fail("planar robot: 'start' and 'goal' may only turn about z (use 'yaw_deg')");
      }
      if (std::abs(s.start.position.z() - s.goal.position.z()) > 1e-12)
        fail("planar robot: 'start' and 'goal' must have the same z");
    }
    // An OMPL.app problem's bounds are set by its reader (ompl_app_problem.cpp), which leaves
    // a start or goal outside them to the validity test, as OMPL.app does.
    for (const auto& [p, name] : {std::pair<const Pose*, const char*>{&s.start, "start"}, {&s.goal, "goal"}})
      if (!omplAppFrame_ && (((p->position - s.bounds.lo).array() < 0).any() || ((p->position - s.bounds.hi).array() > 0).any()))
        fail("'" + std::string(name) + "' position is outside the " + (root["volume"] ? "volume" : "workspace"));
    readRuns(root, s);
    return s;
  }

 private:
  /// 'world' and 'obstacles' (not with 'free_space').
  void readObstacles(const YAML::Node& root, Scenario& s) {
    if (root["free_space"] && (root["obstacles"] || root["world"])) fail("give either 'obstacles' (or 'world') or 'free_space', not both");
    if (root["world"]) {  // OMPL.app's environment: one mesh, closed or not
      const std::string file = scalar<std::string>(root["world"], "world");
      s.obstacles.push_back({"world (" + file + ")", meshFile(root["world"], "world"), false});
    }
    if (root["obstacles"]) {
      const YAML::Node& list = root["obstacles"];
      if (!list.IsSequence()) fail("'obstacles' must be a list");
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string where = "obstacles[" + std::to_string(i) + "]";
        const YAML::Node& o = list[i];
        checkKeys(o, where, {"box", "mesh", "scale", "translate"});
        if (o["box"] && o["mesh"]) fail("'" + where + "' has both 'box' and 'mesh'");
        if (o["box"]) {
          if (o["scale"] || o["translate"]) fail("'" + where + "': 'scale' and 'translate' apply to meshes only");
          const acd::Box3 b = box(o["box"], where + ".box");
          s.obstacles.push_back({where + " (box)", acd::shapes::box(b.lo, b.hi), true});
        } else if (o["mesh"]) {
          s.obstacles.push_back({where + " (" + o["mesh"].as<std::string>() + ")",
                                 transformed(meshFile(o["mesh"], where + ".mesh"), o, where), false});
        } else {
          fail("'" + where + "' needs 'box' or 'mesh'");
        }
      }
    }
  }

  /// 'free_space', or 'workspace' and 'volume' (or the environment's box grown by the robot's reach).
  void readSpace(const YAML::Node& root, Scenario& s) {
    if (root["free_space"]) {
      s.freeSpace = closedFile(root["free_space"], "free_space");
      s.freeSpaceGiven = true;
      s.workspace = acd::boundingBox(s.freeSpace);
      if (root["workspace"] || root["volume"]) fail("'workspace' is taken from 'free_space'; remove one of them");
      s.bounds = s.workspace;
    } else if (root["workspace"]) {
      s.workspace = box(root["workspace"], "workspace");
      s.bounds = root["volume"] ? box(root["volume"], "volume") : s.workspace;
    } else {
      // OMPL.app: the reference point stays in `volume` (default: the environment's bounding
      // box) while the robot may reach out of it; the workspace is grown by the robot's reach.
      if (root["volume"]) {
        s.bounds = box(root["volume"], "volume");
      } else {
        if (s.obstacles.empty()) fail("missing key 'workspace' (or 'volume', 'world' or 'free_space')");
        acd::Box3 b = acd::boundingBox(s.obstacles.front().triangles);
        for (const Obstacle& o : s.obstacles) {
          const acd::Box3 ob = acd::boundingBox(o.triangles);
          b.lo = b.lo.cwiseMin(ob.lo), b.hi = b.hi.cwiseMax(ob.hi);
        }
        if (!((b.hi - b.lo).array() > 0).all()) fail("the environment is flat; give 'volume' or 'workspace'");
        s.bounds = b;
      }
      const double reach = s.robot.boundingRadius();
      s.workspace = {s.bounds.lo - acd::Vec3::Constant(reach), s.bounds.hi + acd::Vec3::Constant(reach)};
    }
    if (((s.bounds.lo - s.workspace.lo).array() < 0).any() || ((s.bounds.hi - s.workspace.hi).array() > 0).any())
      fail("'volume' must lie inside 'workspace'");
  }

  /// The samplers, the counts, the PRM's and the acd sampler's settings, the seed and the output folder.
  void readRuns(const YAML::Node& root, Scenario& s) {
    if (root["samplers"]) {
      const YAML::Node& list = root["samplers"];
      if (!list.IsSequence() || list.size() == 0) fail("'samplers' must be a non-empty list");
      s.samplers.clear();
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string name = scalar<std::string>(list[i], "samplers[" + std::to_string(i) + "]");
        const auto& known = knownSamplers();
        if (std::find(known.begin(), known.end(), name) == known.end())
          fail("unknown sampler '" + name + "' (known: uniform, acd, gaussian, obstacle_based, bridge_test)");
        if (std::find(s.samplers.begin(), s.samplers.end(), name) != s.samplers.end())
          fail("sampler '" + name + "' listed twice");
        s.samplers.push_back(name);
      }
    }
    if (root["samples"]) s.samples = positiveInt(root["samples"], "samples");
    if (root["trials"]) s.trials = positiveInt(root["trials"], "trials");
    if (root["sweep_trials"]) s.sweepTrials = positiveInt(root["sweep_trials"], "sweep_trials");
    if (root["sweep"]) {
      const YAML::Node& list = root["sweep"];
      if (!list.IsSequence() || list.size() == 0) fail("'sweep' must be a non-empty list of sample counts");
      s.sweep.clear();
      for (std::size_t i = 0; i < list.size(); ++i) s.sweep.push_back(positiveInt(list[i], "sweep[" + std::to_string(i) + "]"));
    }
    if (root["prm"]) {
      const YAML::Node& n = root["prm"];
      checkKeys(n, "prm", {"neighbors", "resolution"});
      if (n["neighbors"]) s.prm.neighbors = positiveInt(n["neighbors"], "prm.neighbors");
      if (n["resolution"]) s.prm.resolution = positive(n["resolution"], "prm.resolution");
      if (s.prm.resolution >= 0.5) fail("'prm.resolution' must be below 0.5 (a fraction of the space's extent)");
    }
    if (root["acd"]) {
      const YAML::Node& n = root["acd"];
      checkKeys(n, "acd", {"tau", "spread", "uniform_fraction", "orientation_tries", "aligned_fraction", "tilt",
                                 "thread_fraction"});
      if (n["orientation_tries"]) s.acd.orientationTries = positiveInt(n["orientation_tries"], "acd.orientation_tries");
      if (n["tau"]) s.acd.tau = positive(n["tau"], "acd.tau");
      if (n["spread"]) s.acd.spread = positive(n["spread"], "acd.spread");
      if (n["uniform_fraction"]) {
        s.acd.uniformFraction = finite(n["uniform_fraction"], "acd.uniform_fraction");
        if (s.acd.uniformFraction < 0 || s.acd.uniformFraction > 1) fail("'acd.uniform_fraction' must be in [0, 1]");
      }
      if (n["aligned_fraction"]) {
        s.acd.alignedFraction = finite(n["aligned_fraction"], "acd.aligned_fraction");
        if (s.acd.alignedFraction < 0 || s.acd.alignedFraction > 1) fail("'acd.aligned_fraction' must be in [0, 1]");
      }
      if (n["thread_fraction"]) {
        s.acd.threadFraction = finite(n["thread_fraction"], "acd.thread_fraction");
        if (s.acd.threadFraction < 0 || s.acd.threadFraction > 1) fail("'acd.thread_fraction' must be in [0, 1]");
      }
      if (n["tilt"]) {
        s.acd.tilt = finite(n["tilt"], "acd.tilt");
        if (s.acd.tilt < 0) fail("'acd.tilt' must not be negative");
      }
    }
    if (root["seed"]) {
      const long long seed = scalar<long long>(root["seed"], "seed");
      if (seed <= 0 || seed > 0xFFFFFFFFll) fail("'seed' must be in 1..4294967295");
      s.seed = static_cast<unsigned>(seed);
    }
    if (root["output"]) s.outputDir = scalar<std::string>(root["output"], "output");
  }

  std::string source_;
  std::string baseDir_;
};

}  // namespace

Scenario parseScenario(const std::string& yamlText, const std::string& sourceName, const std::string& baseDir) {
  Parser parser(sourceName, baseDir);
  YAML::Node root;
  try {
    root = YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    parser.fail("not valid YAML: " + std::string(e.what()));
  }
  try {
    Scenario s = parser.scenario(root);
    s.path = sourceName;
    if (s.name.empty()) s.name = std::filesystem::path(sourceName).stem().string();
    return s;
  } catch (const YAML::Exception& e) {
    parser.fail(e.what());
  }
}

Scenario loadScenario(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScenarioError(path + ": file not found or not readable");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string base = std::filesystem::path(path).parent_path().string();
  return parseScenario(text.str(), path, base);
}

}  // namespace planner
