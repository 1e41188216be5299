// acd convert IN OUT: a mesh from any format acd reads into any format it writes, as read (no
// repair): what the benchmarks hand to tools that read OBJ only (bench/compare_peers.sh).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

/// Adds the convert subcommand.
CLI::App* addConvertCommand(CLI::App& app);

/// Runs it (after parsing). Returns the process exit code.
int runConvert();

}  // namespace acdcli
