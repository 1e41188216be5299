#include "compare.hpp"

#include "exact_cgal.hpp"

#include <cstdio>

namespace pointloc {

namespace {

/// Times a method on the first k points, keeping its answers to check them against `truth`.
class Timer {
 public:
  Timer(Run& run, std::uint64_t k) : run_(run), k_(k), truth_(k), answer_(k) {
    overBlocks(*run.arena, k, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
      for (std::uint64_t i = i0; i < i1; ++i) truth_[i] = run.exact->inside((*run.points)(i)) ? 1 : 0;
      return std::uint64_t{0};
    });
  }

  /// Times `test` on the first k points in `arena`.
  template <class Test>
  Method timeOn(Method m, tbb::task_arena& a, const Test& test) {
    const acd::BoxPointStream& points = *run_.points;
    for (int r = 0; r < run_.p.repeat; ++r) {
      const auto t = Clock::now();
      const bool alone = a.max_concurrency() == 1;
      const double cpu = cpuNow(alone);
      m.inside = overBlocks(a, k_, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
        std::uint64_t in = 0;
        for (std::uint64_t i = i0; i < i1; ++i) {
          answer_[i] = test(points(i)) ? 1 : 0;
          in += answer_[i];
        }
        return in;
      });
      m.runs.push_back(secondsSince(t));
      m.cpuRuns.push_back(cpuNow(alone) - cpu);
    }
    m.seconds = median(m.runs);
    m.points = k_;
    m.threads = a.max_concurrency();
    m.disagreements = disagreements();
    return m;
  }

 private:
  std::uint64_t disagreements() const {
    std::uint64_t d = 0;
    for (std::uint64_t i = 0; i < k_; ++i) d += truth_[i] != answer_[i] ? 1 : 0;
    return d;
  }

  Run& run_;
  std::uint64_t k_;
  std::vector<std::uint8_t> truth_, answer_;
};

void compareModel(Run& run, Timer& timer, tbb::task_arena& single, std::vector<Method>& methods) {
  if (run.progress) std::fprintf(stderr, "compare: CGAL Side_of_triangle_mesh\n");
  const CgalSideOfMesh cgal(run.mesh);
  const std::string cgalName = "model: CGAL Side_of_triangle_mesh";
  if (cgal.ok()) {
    const auto test = [&](const acd::Vec3& q) { return cgal.inside(q); };
    methods.push_back(timer.timeOn({cgalName, true, cgal.buildSeconds()}, single, test));
    methods.push_back(timer.timeOn({cgalName, true, cgal.buildSeconds()}, *run.arena, test));
  } else {
    methods.push_back({cgalName, true, 0, 1, 0, 0, 0, std::nullopt, cgal.error()});
  }
  const acd::InsideTest& exact = *run.exact;
  methods.push_back(timer.timeOn({"model: acd::InsideTest", true, run.exactBuildSeconds}, single,
                                 [&](const acd::Vec3& q) { return exact.inside(q); }));
  methods.push_back(timer.timeOn({"model: acd::InsideTest", true, run.exactBuildSeconds}, *run.arena,
                                 [&](const acd::Vec3& q) { return exact.inside(q); }));
}

void compareExactPieces(Run& run, Timer& timer, tbb::task_arena& single, Comparison& c) {
  if (run.progress) std::fprintf(stderr, "compare: exact convex decomposition (limit %g s)\n", run.p.ecdTimeLimit);
  c.ecd = exactPieces(run.mesh, run.p.ecdTimeLimit);
  const std::string ecdName = "ECD pieces (grid)";
  if (!c.ecd.finished) {
    c.methods.push_back({ecdName, true, c.ecd.seconds, 0, 0, 0, 0, std::nullopt,
                         !c.ecd.available ? c.ecd.note : (c.ecd.refused ? "refused: " : "unfinished: ") + c.ecd.note});
    return;
  }
  acd::HullSet& locator = c.ecdLocator.emplace(run.slack);
  for (const acd::TriMesh& piece : c.ecd.pieces) locator.add(piece);
  const auto tIndex = Clock::now();
  locator.buildIndex(run.box, run.p.gridCells, *run.arena);
  const double ecdIndexSeconds = secondsSince(tIndex);
  const auto test = [&](const acd::Vec3& q) { return locator.inside(q); };
  c.methods.push_back(timer.timeOn({ecdName, true, c.ecd.seconds + ecdIndexSeconds}, single, test));
  Method all{ecdName, true, c.ecd.seconds + ecdIndexSeconds, run.usedThreads, run.p.samples};
  for (int r = 0; r < run.p.repeat; ++r) {
    const auto t = Clock::now();
    const double cpu = cpuNow(false);
    all.inside = overBlocks(*run.arena, run.p.samples, run.progress ? "locating in the ECD" : nullptr,
                            [&](std::uint64_t i0, std::uint64_t i1) { return locator.countInside(*run.points, i0, i1); });
    all.runs.push_back(secondsSince(t));
    all.cpuRuns.push_back(cpuNow(false) - cpu);
  }
  all.seconds = median(all.runs);
  c.methods.push_back(all);
}

}  // namespace

Comparison compareMethods(Run& run) {
  Comparison c;
  Timer timer(run, run.p.compareSamples);
  tbb::task_arena single = acd::workerArena(1);

  Method acdAll{"ACD hulls (grid)", false, run.decomposeSeconds + run.indexSeconds, run.usedThreads, run.p.samples,
                run.locateSeconds, run.inside};
  acdAll.runs = run.locateRuns;
  acdAll.cpuRuns = run.locateCpuRuns;
  c.methods.push_back(acdAll);
  c.methods.push_back(timer.timeOn({"ACD hulls (grid)", false, run.decomposeSeconds + run.indexSeconds}, single,
                                   [&](const acd::Vec3& q) { return run.hullInside(q); }));
  compareModel(run, timer, single, c.methods);
  compareExactPieces(run, timer, single, c);
  return c;
}

}  // namespace pointloc
