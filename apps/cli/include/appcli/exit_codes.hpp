// Exit codes shared by the programs (acd, tetmesh, pointloc, skeleton, planner; docs/ERRORS.md): each uses
// the ones that apply to it, so the same failure ends with the same code whichever program met it.
#pragma once

#include <acd/status.hpp>

namespace appcli {

enum Exit : int {
  kOk = 0,
  kUsage = 1,          // bad command line (CLI11 prints the reason)
  kBadInput = 2,       // the model cannot be read or is not a valid solid
  kBadParameter = 3,   // an option out of range
  kUnresolved = 4,     // finished, but some component still exceeds tau (see the report)
  kOutputFailed = 5,   // could not write results
  kInternal = 6,       // a bug (or a step that should not fail did): please report
};

/// The exit code for a failed libacd Status (kOk for an ok one).
inline int exitFor(const acd::Status& s) {
  switch (s.code) {
    case acd::StatusCode::Ok: return kOk;
    case acd::StatusCode::InvalidParameter: return kBadParameter;
    case acd::StatusCode::InternalError: return kInternal;
    default: return kBadInput;
  }
}

/// The exit code after CLI11 handled a parse error or --help (CLI::App::exit's return value).
inline int usageExit(int cli11Exit) { return cli11Exit == 0 ? kOk : kUsage; }

}  // namespace appcli
