// acd decompose, simulator-ready output (simulator.cpp): the options --tau-abs, --max-hulls,
// --max-hull-vertices and --density of the post-passes (libacd: acd/post_passes.hpp), and
// --format, the simulator files written from the result.
#pragma once

#include <acd/decompose.hpp>
#include <acd/post_passes.hpp>
#include <acd/simulator_export.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace acdcli {

struct SimulatorArgs {
  double tauAbs = -1.0;            // tau as a length in the input's units (< 0: not given)
  int maxHulls = 0;                // 0: no budget
  int maxHullVertices = 0;         // 0: no cap
  double density = 1000.0;         // mass per unit length cubed (kg/m^3 for a model in metres)
  std::vector<std::string> formats;
  std::vector<acd::SimFormat> parsed;
  acd::PostPassOptions post;       // the options given, for the library (validateSimulatorArgs)
  CLI::Option* tauOption = nullptr;  // -t, to refuse -t together with --tau-abs
};

/// Adds the options to `decompose`.
void addSimulatorOptions(CLI::App& decompose, SimulatorArgs& args);

/// Whether any simulator option was given (they apply to solid decomposition only).
bool simulatorRequested(const SimulatorArgs& args);

/// Checks the values before any work and fills `post` and `parsed`; returns an exit code (0:
/// fine), the reason on stderr.
int validateSimulatorArgs(SimulatorArgs& args, const CLI::App& decompose);

/// --tau-abs: sets options.tau to D in the normalised units of `mesh` (as decompose() will
/// normalise it). Returns an exit code.
int resolveTauAbs(const SimulatorArgs& args, const acd::TriMesh& mesh, acd::DecomposeOptions& options);

/// After decompose(): acd::applyPostPasses (d's components and hulls replaced), with the
/// budget's note on stderr. Returns an exit code; a failure's message on stderr.
int applyPostPasses(const SimulatorArgs& args, acd::Decomposition& d, bool quiet, acd::PostPassResult& result);

/// Writes the --format files into `out`: the hulls of `d`, the input mesh as the visual, the
/// model named after its file; adds "outputs" to `report`. Returns an exit code.
int writeSimulatorOutputs(const SimulatorArgs& args, const acd::Decomposition& d, const acd::TriMesh& input,
                          const std::string& modelPath, const std::string& out, nlohmann::json& report);

}  // namespace acdcli
