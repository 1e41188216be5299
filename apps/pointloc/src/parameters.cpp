#include "parameters.hpp"

#include <appcli/exit_codes.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace pointloc {

using appcli::kBadParameter;
using appcli::kOk;
using appcli::kOutputFailed;

bool parseCount(const std::string& s, double max, bool allowZero, std::uint64_t& out) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0' || !std::isfinite(v)) return false;
  if (v != std::floor(v) || v > max || v < 0 || (!allowZero && v == 0)) return false;
  out = static_cast<std::uint64_t>(v);
  return true;
}

int checkParameters(Parameters& p) {
  if (!parseCount(p.samplesText, 1e10, false, p.samples)) {
    return kConsole.failf(kBadParameter, "--samples '%s' is not a positive integer <= 1e10", p.samplesText.c_str());
  }
  char* end = nullptr;
  p.tau = std::strtod(p.tauText.c_str(), &end);
  if (p.tauText.empty() || *end != '\0' || !(p.tau > 0.0 && p.tau <= 2.0)) {
    return kConsole.failf(kBadParameter, "--tau '%s' must be a number in (0, 2]", p.tauText.c_str());
  }
  if (p.threads < 0) {
    return kConsole.failf(kBadParameter, "--threads %d must be >= 0", p.threads);
  }
  if (p.exactText.empty()) {
    p.exactSamples = std::min<std::uint64_t>(p.samples, 2000000);
  } else if (!parseCount(p.exactText, 1e10, true, p.exactSamples)) {
    return kConsole.failf(kBadParameter, "--exact-samples '%s' is not a non-negative integer", p.exactText.c_str());
  } else {
    p.exactSamples = std::min(p.exactSamples, p.samples);
  }
  if (p.compareText.empty()) {
    p.compareSamples = std::min<std::uint64_t>(p.samples, 1000000);
  } else if (!parseCount(p.compareText, 1e8, false, p.compareSamples)) {  // two bytes of answers per point are kept
    return kConsole.failf(kBadParameter, "--compare-samples '%s' is not a positive integer <= 1e8", p.compareText.c_str());
  } else {
    p.compareSamples = std::min(p.compareSamples, p.samples);
  }
  if (!(p.ecdTimeLimit > 0) || !std::isfinite(p.ecdTimeLimit)) {
    return kConsole.failf(kBadParameter, "--ecd-time-limit %g must be a positive number of seconds", p.ecdTimeLimit);
  }
  if (p.repeat < 1 || p.repeat > 100) {
    return kConsole.failf(kBadParameter, "--repeat %d must be in [1, 100]", p.repeat);
  }
  if (p.gridCells == 0 || p.gridCells > (1u << 24)) {
    return kConsole.failf(kBadParameter, "--grid-cells %zu must be in [1, 16777216]", p.gridCells);
  }
  // Output files are checked before the work, not after a long run.
  for (const std::string* out : {&p.jsonPath, &p.dumpPath}) {
    if (out->empty()) continue;
    if (!std::ofstream(*out, std::ios::app)) {
      return kConsole.failf(kOutputFailed, "cannot write %s", out->c_str());
    }
  }
  return kOk;
}

}  // namespace pointloc
