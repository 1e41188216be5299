// acd report OUT: a static OUT/index.html over a batch (OUT/batch.jsonl): one card per mesh with
// a picture, parts, tau, IoU and excess volume when evaluated, time, memory and status,
// sortable; a card opens a WebGL view of the mesh's hulls. Needs no network and no library.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace acdcli {

struct ReportOptions {
  std::string out;        // the batch's output folder
  bool pictures = true;   // render OUT/report/NAME.png with scripts/render.sh (f3d) when available
  bool evaluate = false;  // run `acd evaluate` on each decomposed mesh (IoU, excess volume)
  int jobs = 0;           // pictures and evaluations at the same time (0: the number of cores)
};

CLI::App* addReportCommand(CLI::App& app);

/// Runs after parsing when the report subcommand was given. Returns the process exit code.
int runReport();

/// Writes OUT/index.html and OUT/report/; returns an exit code (0, 2 no batch.jsonl, 5 output).
int writeReport(const ReportOptions& options);

}  // namespace acdcli
