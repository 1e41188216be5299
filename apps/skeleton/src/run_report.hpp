// A skeleton run's results: per model its skeletons as JSON and OBJ (and tubes), report.json
// for the whole run, and the summary table on standard output.
#pragma once

#include "skeleton_run.hpp"

#include <vector>

namespace skeleton {

/// Writes the files; kOk or kOutputFailed after a message. `unresolved`: a component of some
/// model still exceeds tau.
int writeRunFiles(const RunParameters& p, const std::vector<Model>& models, bool& unresolved);

/// The table of nodes and distances per model.
void printTable(const std::vector<Model>& models);

}  // namespace skeleton
