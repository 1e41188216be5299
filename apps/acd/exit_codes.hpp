// Exit codes of every `acd` subcommand (docs/ERRORS.md), and the one way a failed Status is told.
#pragma once

#include <acd/status.hpp>

#include <cstdio>
#include <string>

namespace acdcli {

enum Exit : int {
  kOk = 0,
  kUsage = 1,           // bad command line (CLI11 prints the reason)
  kBadInput = 2,        // the model cannot be read or is not a valid solid
  kBadParameter = 3,    // tau, epsilon, delta, threads out of range
  kUnresolved = 4,      // finished, but some component still exceeds tau (see report)
  kUnfinished = 4,      // --exact: a time or memory cap stopped the exact decomposition
  kOutputFailed = 5,    // could not write results
  kInternal = 6,        // a bug: please report
  kBatchFailures = 7,   // batch: some meshes failed (crash, cap, refused input); see OUT/batch.jsonl
};

inline int exitFor(const acd::Status& s) {
  switch (s.code) {
    case acd::StatusCode::Ok: return kOk;
    case acd::StatusCode::InvalidParameter: return kBadParameter;
    case acd::StatusCode::InternalError: return kInternal;
    default: return kBadInput;
  }
}

/// Prints "acd: WHERE: message" (once: readers' messages already start with the path) and
/// returns the exit code for the status.
inline int fail(const std::string& where, const acd::Status& s) {
  if (s.message.rfind(where, 0) == 0)
    std::fprintf(stderr, "acd: %s\n", s.message.c_str());
  else
    std::fprintf(stderr, "acd: %s: %s\n", where.c_str(), s.message.c_str());
  return exitFor(s);
}

inline int outputFailed(const std::string& what) {
  std::fprintf(stderr, "acd: output: cannot write %s\n", what.c_str());
  return kOutputFailed;
}

}  // namespace acdcli
