// The experiment of the paper's Figure 3: PRM with a fixed number of samples, per sampler,
// over seeded trials; success = start and goal in one roadmap component.
#pragma once

#include "body_parts.hpp"
#include "fixed_prm.hpp"
#include "openings.hpp"
#include "problem.hpp"
#include "scenario.hpp"

#include <acd/decompose.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace planner {

/// Free space, its ACD and the openings: the preprocessing of the ACD sampler.
struct Preprocessing {
  std::vector<std::string> obstacleSolids;   // per obstacle: "name: how it was made a solid" (SolidObstacle::summary)
  std::vector<NamedSolid> solids;            // what the free space was cut from, for the messages
  WrapSettings wrap;                         // as resolved for the obstacles
  double robotThickness = 0.0;               // Robot::thickness(), for the report
  bool wrapped = false;                      // some obstacle piece was wrapped
  acd::TriMesh freeSpace;
  std::string freeSpaceMethod;        // "given", "corefinement" or "nef"
  int cavities = 0;                   // obstacles floating in the free space
  int freeSpacePieces = 1;            // pieces decomposed apart (cut through the cavities)
  std::vector<acd::TriMesh> components;
  std::vector<Opening> openings;
  // The parts and gaps of the robot (its frame) and of the obstacles (the world), for the
  // threading poses; empty for a robot that does not turn in 3D (a point, a sphere, SE(2)).
  BodyParts robotParts, obstacleParts;
  double solidSeconds = 0.0, freeSpaceSeconds = 0.0, decomposeSeconds = 0.0, openingsSeconds = 0.0, partsSeconds = 0.0;
  double totalSeconds() const {
    return solidSeconds + freeSpaceSeconds + decomposeSeconds + openingsSeconds + partsSeconds;
  }
};

/// The obstacles made solids (solid_obstacles.hpp), the free space, its ACD and the openings.
/// The ACD part is skipped when the scenario does not compare the acd sampler.
/// \throw ScenarioError when the free space cannot be built or decomposed (message says why).
Preprocessing preprocess(const Scenario& scenario);

struct Trial {
  RoadmapOutcome outcome;
  double seconds = 0.0;      // roadmap construction: sampling, validity checks, connections
  long checks = 0;           // state validity checks
};

/// One trial: sampler `sampler`, N = `samples`, seeded by trialSeed(scenario seed, ...).
Trial runTrial(PlanningProblem& problem, const std::string& sampler, int samples, int trial);

struct SamplerSummary {
  std::string sampler;
  int samples = 0;
  int trials = 0;
  int successes = 0;
  double rate = 0.0, ciLow = 0.0, ciHigh = 0.0;   // Wilson score interval, 95 %
  double meanSeconds = 0.0;
  double meanMilestones = 0.0, meanEdges = 0.0;
  double meanPathLength = 0.0;                     // over successful trials; 0 when none
  double meanChecks = 0.0;
  int exhaustedTrials = 0;                         // trials that stopped short of N milestones
};

/// Wilson score interval for `successes` out of `trials` at z = 1.96.
void wilson(int successes, int trials, double& low, double& high);

struct SamplerRuns {
  SamplerSummary summary;
  std::vector<Trial> trials;
};

/// Runs `trials` trials of each sampler at `samples` milestones; `progress` (may be empty)
/// is called after each trial.
std::vector<SamplerRuns> runExperiment(PlanningProblem& problem, const std::vector<std::string>& samplers, int samples,
                                       int trials, const std::function<void(const std::string&, int, int)>& progress = {});

}  // namespace planner
