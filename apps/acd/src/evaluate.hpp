// acd evaluate MODEL HULLS.obj: how well any set of hulls approximates a model (evaluate.cpp).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

/// Adds the evaluate subcommand.
CLI::App* addEvaluateCommand(CLI::App& app);

/// Runs it (after parsing). Returns the process exit code.
int runEvaluate();

}  // namespace acdcli
