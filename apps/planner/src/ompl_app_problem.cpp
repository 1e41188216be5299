#include "ompl_app_problem.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace planner {

namespace {

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// OMPL.app's planner keys (its benchmark's list): a key is a planner when it is one of these,
/// a parameter of the last such planner when it starts with one and a dot.
const std::vector<std::string>& knownPlannerKeys() {
  static const std::vector<std::string> keys{"rrtconnect", "lazyrrt",   "lazyprm", "kpiece",      "bkpiece", "lbkpiece",
                                             "est",        "sbl",       "prm",     "rrt",         "stride",  "pdst",
                                             "rrtstar",    "prmstar",   "lazyprmstar", "spars",   "spars2",  "lbtrrt",
                                             "trrt",       "fmt",       "syclopest", "sycloprrt", "aps"};
  return keys;
}

/// The file as (section.key, value) in file order, repeats kept ('#' starts a comment).
std::vector<std::pair<std::string, std::string>> entries(const std::string& text, const std::string& source) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(text);
  std::string line, section;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    line = trimmed(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') throw ScenarioError(source + ":" + std::to_string(number) + ": a section header needs ']'");
      section = lower(trimmed(line.substr(1, line.size() - 2)));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw ScenarioError(source + ":" + std::to_string(number) + ": not 'key=value': " + line);
    out.emplace_back(section + "." + trimmed(line.substr(0, eq)), trimmed(line.substr(eq + 1)));
  }
  return out;
}

class Reader {
 public:
  Reader(std::string source, const std::string& text) : source_(std::move(source)) {
    for (const auto& [key, value] : entries(text, source_)) {
      if (key.rfind("planner.", 0) == 0)
        plannerLine(lower(key.substr(8)), value);
      else
        values_[key] = value;  // the last one wins, as in OMPL.app
    }
  }

  bool has(const std::string& key) const { return values_.count(key) > 0; }

  const std::string& text(const std::string& key) const {
    const auto it = values_.find(key);
    if (it == values_.end()) throw ScenarioError(source_ + ": missing [" + section(key) + "] " + field(key));
    return it->second;
  }

  double number(const std::string& key) const {
    const std::string& v = text(key);
    try {
      std::size_t used = 0;
      const double d = std::stod(v, &used);
      if (used == v.size() && std::isfinite(d)) return d;
    } catch (const std::exception&) {
    }
    throw ScenarioError(source_ + ": [" + section(key) + "] " + field(key) + " is not a number: '" + v + "'");
  }

  const std::vector<PlannerEntry>& planners() const { return planners_; }

 private:
  static std::string section(const std::string& key) { return key.substr(0, key.find('.')); }
  static std::string field(const std::string& key) { return key.substr(key.find('.') + 1); }

  void plannerLine(const std::string& key, const std::string& value) {
    for (const std::string& name : knownPlannerKeys()) {
      if (key == name) {
        planners_.push_back({name, {}});
        return;
      }
      if (key.rfind(name + ".", 0) == 0) {
        auto last = std::find_if(planners_.rbegin(), planners_.rend(), [&](const PlannerEntry& p) { return p.name == name; });
        if (last == planners_.rend()) {
          planners_.push_back({name, {}});
          last = planners_.rbegin();
        }
        last->params.emplace_back(key.substr(name.size() + 1), value);
        return;
      }
    }
    // OMPL.app ignores what it does not know; so does this reader.
  }

  std::string source_;
  std::map<std::string, std::string> values_;
  std::vector<PlannerEntry> planners_;
};

YAML::Node list3(double x, double y, double z) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.push_back(x), n.push_back(y), n.push_back(z);
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

bool isSe2(const Reader& r) {
  auto has = [&](const std::string& k) { return r.has("problem." + k); };
  for (const char* w : {"start", "goal"}) {
    const std::string s(w);
    if (!has(s + ".x") || !has(s + ".y") || !has(s + ".theta")) return false;
    if (has(s + ".z") || has(s + ".axis.x") || has(s + ".axis.y") || has(s + ".axis.z")) return false;
  }
  return true;
}

YAML::Node pose(const Reader& r, const std::string& which, bool se2) {
  const std::string k = "problem." + which + ".";
  YAML::Node n;
  if (se2) {
    n["position"] = list3(r.number(k + "x"), r.number(k + "y"), 0.0);
    n["axis"] = list3(0, 0, 1);
  } else {
    n["position"] = list3(r.number(k + "x"), r.number(k + "y"), r.number(k + "z"));
    n["axis"] = list3(r.number(k + "axis.x"), r.number(k + "axis.y"), r.number(k + "axis.z"));
  }
  n["theta"] = r.number(k + "theta");
  return n;
}

}  // namespace

bool isOmplAppProblem(const std::string& path) { return lower(std::filesystem::path(path).extension().string()) == ".cfg"; }

Scenario parseOmplAppProblem(const std::string& text, const std::string& sourceName, const std::string& baseDir) {
  const Reader r(sourceName, text);
  const bool se2 = isSe2(r);
  YAML::Node root;
  root["name"] = r.has("problem.name") ? r.text("problem.name") : std::filesystem::path(sourceName).stem().string();
  root["world"] = r.text("problem.world");
  YAML::Node robot;
  robot["type"] = "mesh";
  robot["mesh"] = r.text("problem.robot");
  robot["center"] = true;
  if (se2) robot["planar"] = true;
  root["robot"] = robot;
  root["start"] = pose(r, "start", se2);
  root["goal"] = pose(r, "goal", se2);
  root["validity"] = "triangles";
  root["frame"] = "ompl_app";
  const bool volume = se2 ? r.has("problem.volume.min.x") && r.has("problem.volume.min.y") && r.has("problem.volume.max.x") &&
                                r.has("problem.volume.max.y")
                          : r.has("problem.volume.min.x") && r.has("problem.volume.min.y") && r.has("problem.volume.min.z") &&
                                r.has("problem.volume.max.x") && r.has("problem.volume.max.y") && r.has("problem.volume.max.z");
  Scenario s;
  try {
    s = parseScenario(YAML::Dump(root), sourceName, baseDir);
  } catch (const YAML::Exception& e) {
    throw ScenarioError(sourceName + ": " + e.what());
  }
  // The reference point's bounds, as OMPL.app sets them: `volume`, else the box of the
  // environment's vertices grown to hold the start and the goal (its bounds factor 1, add 0).
  acd::Box3 env = s.bounds;  // parseScenario's default: the environment's box
  acd::Box3 b = env;
  for (const Pose* p : {&s.start, &s.goal}) b.lo = b.lo.cwiseMin(p->position), b.hi = b.hi.cwiseMax(p->position);
  if (volume) {
    b.lo.x() = r.number("problem.volume.min.x"), b.hi.x() = r.number("problem.volume.max.x");
    b.lo.y() = r.number("problem.volume.min.y"), b.hi.y() = r.number("problem.volume.max.y");
    if (!se2) b.lo.z() = r.number("problem.volume.min.z"), b.hi.z() = r.number("problem.volume.max.z");
    if (!((b.hi - b.lo).array() >= 0).all()) throw ScenarioError(sourceName + ": [problem] volume: min exceeds max");
  }
  if (se2) b.lo.z() = std::min(0.0, env.lo.z()), b.hi.z() = std::max(0.0, env.hi.z());  // SE(2): z is not bounded
  s.bounds = b;
  // No walls in OMPL.app: the workspace's walls stand beyond the robot's reach.
  const double reach = s.robot.boundingRadius();
  const acd::Vec3 margin = acd::Vec3::Constant(1.01 * reach + 1e-3 * (b.hi - b.lo).norm());
  s.workspace = {b.lo - margin, b.hi + margin};
  if (r.has("benchmark.time_limit")) s.race.timeLimit = r.number("benchmark.time_limit");
  if (r.has("benchmark.run_count")) s.race.runs = static_cast<int>(r.number("benchmark.run_count"));
  if (!(s.race.timeLimit > 0) || s.race.runs <= 0)
    throw ScenarioError(sourceName + ": [benchmark] time_limit and run_count must be positive");
  s.race.planners = r.planners();
  return s;
}

Scenario loadOmplAppProblem(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScenarioError(path + ": cannot read");
  std::stringstream text;
  text << in.rdbuf();
  Scenario s = parseOmplAppProblem(text.str(), path, std::filesystem::path(path).parent_path().string());
  s.path = path;
  return s;
}

}  // namespace planner
