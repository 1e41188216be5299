// acd table: the paper's Table 1 (ACD against exact decomposition) and the data of its
// Figures 18-19 (components and time against tau, with and without feature grouping).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

CLI::App* addTableCommand(CLI::App& app);

/// Runs after parsing when the table subcommand was given. Returns the process exit code.
int runTable();

}  // namespace acdcli
