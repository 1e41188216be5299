// --compare: the same points answered by other methods — the model itself (CGAL
// Side_of_triangle_mesh, acd::InsideTest) and its exact convex decomposition — each timed on one
// and on all threads and checked against acd::InsideTest.
#pragma once

#include "exact_pieces.hpp"
#include "run.hpp"

#include <acd/algo/hull_set.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pointloc {

/// One row of the --compare table: one way of answering "is point i inside?".
struct Method {
  std::string name;
  bool exact = false;           // answers the model's own question exactly
  double prepareSeconds = 0.0;  // decomposition and index
  int threads = 1;
  std::uint64_t points = 0;     // points timed
  double seconds = 0.0;         // location time for `points`
  std::uint64_t inside = 0;     // on the first `points`
  std::optional<std::uint64_t> disagreements;  // with acd::InsideTest on the compare subsample
  std::string note;             // why the row has no figures
  std::vector<double> runs;     // seconds of each repetition; `seconds` is their median
  std::vector<double> cpuRuns;  // CPU seconds (all threads) of each repetition

  double cpuSeconds() const { return median(cpuRuns); }

  bool measured() const { return points > 0 && note.empty(); }
  double rate() const { return seconds > 0 ? static_cast<double>(points) / seconds : 0.0; }
  double secondsFor(std::uint64_t n) const { return seconds * static_cast<double>(n) / static_cast<double>(points); }
};

struct Comparison {
  std::vector<Method> methods;
  ExactPieces ecd;
  std::optional<acd::HullSet> ecdLocator;
};

/// Times every method on the first K points (the ACD hulls on all N as well).
Comparison compareMethods(Run& run);

}  // namespace pointloc
