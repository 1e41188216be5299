// acd batch: decompose whole folders of meshes, each in its own capped worker process, with a
// content-hash cache (re-runs skip finished meshes, interrupted batches resume), one JSON line
// per mesh in OUT/batch.jsonl, a progress bar and a summary table. `--worker`, `--plan` and
// `--summary` are the pieces other schedulers use (python/acd/batch.py runs them on Dask).
#pragma once

#include <CLI/CLI.hpp>

namespace acdcli {

/// Adds the batch subcommand; it accepts every option of `decompose` (call it after all of them
/// are registered) and passes the given ones on to each decomposition.
CLI::App* addBatchCommand(CLI::App& app, const CLI::App& decompose);

/// Runs after parsing when the batch subcommand was given. Returns the process exit code.
int runBatch();

}  // namespace acdcli
