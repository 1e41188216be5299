// acd: approximate convex decomposition from the command line.
//   acd decompose MODEL [-t TAU] ... -o OUTDIR   components, hulls.obj, report.json, summary table
//   acd info MODEL                              mesh diagnosis
//   acd evaluate MODEL HULLS.obj                how well any set of hulls approximates the model
//   acd decompose MODEL --surface [-t TAU] -o OUT surface ACD: patches.obj, hulls.obj, report.json (surface.cpp)
//   acd decompose MODEL --exact [--surface]     exact convex decomposition (exact.cpp)
//   acd batch INPUT... -o OUT                   many meshes in capped workers, cached (batch.cpp)
//   acd report OUT                              index.html over a batch, with a 3D view (report.cpp)
// This file only wires the subcommands to CLI11; each lives in src/<subcommand>.cpp (acd_core).
// Exit codes are listed in exitCodes() and in --help.
#include <acd/version.hpp>

#include <CLI/CLI.hpp>
#include "batch.hpp"
#include "convert.hpp"
#include "decompose.hpp"
#include "evaluate.hpp"
#include "exact.hpp"
#include "exit_codes.hpp"
#include "info.hpp"
#include "report.hpp"

#include <cstdio>
#include <exception>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace acdcli;  // exit codes, shared with the subcommands

namespace {

/// Freed memory stays with the process for the next piece's buffers instead of going back to the
/// kernel and faulting in again: glibc hands blocks above its threshold straight back (munmap,
/// or a trim of the heap's top), and a decomposition allocates and frees such blocks for every
/// candidate cut. Page faults were 4-5 % of the CPU time of a 10k-face model. Both limits are set:
/// setting either stops glibc from raising the mmap threshold on its own.
void keepFreedMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // the largest every glibc accepts
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
         "4 some component still exceeds tau (--exact: a cap stopped it); 5 cannot write output; 6 internal error;\n"
         "7 batch: some meshes failed (see OUT/batch.jsonl); 8 some hull stands off the model by more than tau.";
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedMemory();
  CLI::App app{"acd: approximate convex decomposition of polyhedra (Lien & Amato, SPM 2007).\n"
               "Lengths (tau, epsilon, delta) are in normalised units: the model scaled so that its\n"
               "minimum enclosing sphere has radius 1. Output meshes are in the input's coordinates."};
  app.footer(exitCodes());
  app.set_version_flag("--version", std::string("acd ") + ACD_VERSION);
  app.require_subcommand(1);

  DecomposeArgs da;
  CLI::App* dec = addDecomposeCommand(app, da);
  CLI::App* info = addInfoCommand(app);
  CLI::App* eval = addEvaluateCommand(app);
  // Keep after every other decompose option: --exact adds --surface if no one else has.
  acdcli::addExactOptions(*dec);
  CLI::App* batch = acdcli::addBatchCommand(app, *dec);  // after every decompose option: it takes them all
  CLI::App* report = acdcli::addReportCommand(app);
  CLI::App* convert = acdcli::addConvertCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kUsage;
  }
  try {
    if (*dec) return runDecompose(*dec, da);
    if (*batch) return acdcli::runBatch();
    if (*report) return acdcli::runReport();
    if (*info) return runInfo();
    if (*eval) return runEvaluate();
    if (*convert) return acdcli::runConvert();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "acd: internal error: %s\n", e.what());
    return kInternal;
  }
  return kUsage;
}
