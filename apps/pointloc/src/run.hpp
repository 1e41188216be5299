// One pointloc run, step by step: the model, its decomposition and hull index, the location of
// all N points, the errors against the exact answer on the first M. Each step reads what the
// earlier ones left in `Run`; the report (report.hpp) reads it all.
#pragma once

#include "blocks.hpp"
#include "parameters.hpp"
#include <acd/algo/random.hpp>

#include <acd/algo/hull_set.hpp>
#include <acd/decompose.hpp>
#include <acd/algo/inside.hpp>

#include <tbb/task_arena.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pointloc {

struct Run {
  explicit Run(const Parameters& parameters) : p(parameters) {}

  const Parameters& p;
  Clock::time_point t0 = Clock::now();
  bool progress = false;  // stderr is a terminal

  // readModel
  std::string modelPath;
  acd::TriMesh mesh;
  // decomposeAndIndex
  acd::Decomposition dec;
  double decomposeSeconds = 0;
  acd::Box3 box;
  double boxVolume = 0, slack = 0;
  acd::HullSet hulls{0.0};
  std::vector<int> hullComponent;  // hull index -> component index
  int unresolved = 0;
  std::optional<acd::BoxPointStream> points;
  std::optional<tbb::task_arena> arena;
  int usedThreads = 1;
  double indexSeconds = 0;
  // locateAll
  std::uint64_t inside = 0;
  std::vector<double> locateRuns, locateCpuRuns;
  double locateSeconds = 0, locateCpuSeconds = 0;
  // measureErrors
  std::optional<acd::InsideTest> exact;
  double exactBuildSeconds = 0, exactRunSeconds = 0;
  std::uint64_t exactInside = 0, falseIn = 0, falseOut = 0;
  std::vector<std::uint64_t> byHull;  // false-inside points in each hull
  std::vector<int> order;             // hulls by false-inside points, most first
  double mainSeconds = 0;             // up to here (without --compare)

  /// The hulls' answer as asked (--no-index: every hull tested).
  bool hullInside(const acd::Vec3& q) const { return p.noIndex ? hulls.insideDirect(q) : hulls.inside(q); }
};

/// Reads the model (the default one from the source tree when run elsewhere); refuses an open one.
int readModel(Run& run);
/// Decomposes the model and indexes the hulls over its bounding box.
int decomposeAndIndex(Run& run);
/// Locates all N points (--repeat times, the median time kept); kInternal if two passes disagree.
int locateAll(Run& run);
/// The exact answer on the first M points, timed alone, then the false inside and outside.
void measureErrors(Run& run);
/// --dump: the exactly checked points as CSV.
int dumpPoints(const Run& run);

}  // namespace pointloc
