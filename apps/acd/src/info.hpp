// acd info MODEL: what is wrong with a mesh, and what `acd decompose` would do with it (info.cpp).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

/// Adds the info subcommand.
CLI::App* addInfoCommand(CLI::App& app);

/// Runs it (after parsing). Returns the process exit code.
int runInfo();

}  // namespace acdcli
