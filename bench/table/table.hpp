// acd-table: the paper's Table 1 (ACD against exact decomposition) and the data of its
// Figures 18-19 (components and time against tau, with and without feature grouping).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

/// The table's options, on the program's command line.
void addTableOptions(CLI::App& app);

/// Runs after parsing. Returns the process exit code (apps/acd/exit_codes.hpp).
int runTable();

}  // namespace acdcli
