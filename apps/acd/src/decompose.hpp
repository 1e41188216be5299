// acd decompose MODEL: solid ACD (decompose.cpp), and the choice between it, --surface
// (surface.cpp) and --exact (exact.cpp).
#pragma once

#include "simulator.hpp"

#include <acd/decompose.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace acdcli {

struct DecomposeArgs {
  std::string model;
  std::string out = "acd-out";
  acd::DecomposeOptions options = acd::recommendedOptions();
  bool noGrouping = false;
  bool cutEveryRegion = false;       // --cut-every-region
  bool noMerge = false;
  bool noInvariant = false;          // --no-invariant
  bool invariantFlag = false;        // --invariant: the default since 2026-11-25, still accepted
  std::string mergeScope = "model";  // --merge-scope
  bool noFillHoles = false;
  bool noWrap = false;
  bool noUnion = false;    // --no-union
  bool unionFlag = false;  // --union: the default since 2026-11-29, still accepted
  bool noRepair = false;
  bool surface = false;
  bool quiet = false;
  SimulatorArgs sim;  // --tau-abs, --max-hulls, --max-hull-vertices, --density, --format (simulator.cpp)
  bool perMesh = false;
  std::string mesh;  // with --per-mesh: the name of the scene mesh being decomposed
};

/// Adds the decompose subcommand with the solid ACD's options and --surface (--exact's options
/// and acd batch, which takes them all, are added after it).
CLI::App* addDecomposeCommand(CLI::App& app, DecomposeArgs& args);

/// Runs it (after parsing): checks the combination of modes and options, then solid ACD,
/// --surface or --exact. Returns the process exit code.
int runDecompose(const CLI::App& decompose, DecomposeArgs& args);

}  // namespace acdcli
