// What a decomposition says about the watertight wrap (report.json `input.wrap`).
#pragma once

#include <string>

namespace acd {

struct WrapReport {
  bool used = false;
  std::string reason;        // why: the pieces no repair could close, or components left above tau
  int wrappedPieces = 0;     // pieces of the repaired input that were wrapped
  double alpha = 0.0;        // normalised units
  double offset = 0.0;       // normalised units
  double hausdorff = 0.0;    // two-sided, wrap against the wrapped input pieces, normalised units
  double wrapToInput = 0.0;  // one-sided: how far the wrap strays from the input
  double inputToWrap = 0.0;  // one-sided: how far the input lies from the wrap (inner parts of a
                             // surface that passes through itself lie deep inside the wrap)
  int faces = 0;             // of the wrap
  double seconds = 0.0;      // wrapping and measuring
};

}  // namespace acd
