// Exit codes of every `acd` subcommand (docs/ERRORS.md): the programs' shared codes (apps/cli)
// plus acd's own two, and the one way a failed Status is told.
#pragma once

#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <acd/status.hpp>

#include <string>

namespace acdcli {

using appcli::exitFor;
using appcli::kBadInput;
using appcli::kBadParameter;
using appcli::kInternal;
using appcli::kOk;
using appcli::kOutputFailed;
using appcli::kUnresolved;
using appcli::kUsage;
constexpr int kUnfinished = appcli::kUnresolved;  // --exact: a time or memory cap stopped the exact decomposition
constexpr int kBatchFailures = 7;  // batch: some meshes failed (crash, cap, refused input); see OUT/batch.jsonl
constexpr int kTauNotKept = 8;     // decompose: some hull stands off the model by more than tau (the promise)

/// "acd: ..." on stderr.
inline const appcli::Console& console() {
  static const appcli::Console c("acd");
  return c;
}

/// Prints "acd: WHERE: message" (once: readers' messages already start with the path) and
/// returns the exit code for the status.
inline int fail(const std::string& where, const acd::Status& s) { return console().fail(where, s); }

inline int outputFailed(const std::string& what) { return console().fail(kOutputFailed, "output: cannot write " + what); }

}  // namespace acdcli
