// pointloc's parameters: as given on the command line (text, so that "1e8" is a count) and as
// checked before any model is read.
#pragma once

#include <appcli/console.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace pointloc {

/// "pointloc: ..." on stderr.
inline const appcli::Console kConsole{"pointloc"};

struct Parameters {
  // as given
  std::string model = "data/meshes/elephant.off";
  std::string samplesText = "1e8", tauText = "0.02", exactText, compareText;
  std::string dumpPath, jsonPath;
  int threads = 0;
  std::uint64_t seed = 1;
  bool noIndex = false, compare = false;
  std::size_t gridCells = 1u << 18;
  double ecdTimeLimit = 60.0;
  int repeat = 1;
  // checked (checkParameters)
  std::uint64_t samples = 0, exactSamples = 0, compareSamples = 0;
  double tau = 0.0;
};

/// Parses the counts and tau, checks every range and that the output files can be written;
/// kOk, or the exit code after a one-line message.
int checkParameters(Parameters& p);

/// A positive integer written as a double ("1e8" or "100000000"), at most `max`.
bool parseCount(const std::string& s, double max, bool allowZero, std::uint64_t& out);

}  // namespace pointloc
