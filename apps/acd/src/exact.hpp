// acd decompose --exact [--surface]: the exact convex decompositions (exact.cpp).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace acdcli {

/// Adds --exact and its caps to the decompose subcommand, and --surface when no other mode has
/// added it yet (call it after every other decompose option).
void addExactOptions(CLI::App& decompose);

/// --exact was given (or a --surface that only this file knows about).
bool exactRequested(const CLI::App& decompose);

/// Solid ECD, or surface ECD when --surface was given. Returns the process exit code.
int runExact(const CLI::App& decompose, const std::string& model, const std::string& out, bool quiet);

}  // namespace acdcli
