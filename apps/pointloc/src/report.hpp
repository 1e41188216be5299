// pointloc's report: the table on standard output and the same figures as JSON (--json).
#pragma once

#include "compare.hpp"
#include "run.hpp"

#include <nlohmann/json.hpp>

namespace pointloc {

/// What the --compare table adds to the JSON: its rows and the speed-ups over CGAL.
struct CompareFigures {
  nlohmann::json methods = nlohmann::json::array();
  double vsCgal1 = 0.0, vsCgalAll = 0.0, cgalPerCpu = 0.0;
};

/// The main figures: decomposition, grid, location, errors, the components most in excess.
/// Returns the JSON list of those components.
nlohmann::json printReport(const Run& run);

/// The --compare table.
CompareFigures printComparison(const Run& run, const Comparison& comparison);

/// --json; kOk or kOutputFailed after a message.
int writeJson(const Run& run, const nlohmann::json& top, const Comparison* comparison, const CompareFigures& figures,
              double totalSeconds);

}  // namespace pointloc
