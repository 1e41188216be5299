// acd decompose --surface: surface ACD (surface.cpp).
#pragma once

#include <acd/surface_decompose.hpp>

#include <string>

namespace acdcli {

struct SurfaceArgs {
  std::string model;
  std::string out;
  acd::SurfaceDecomposeOptions options;
  bool quiet = false;
};

/// Surface ACD of the model: patches.obj (one object per patch), hulls.obj, report.json and a
/// summary table. Returns the process exit code.
int runSurfaceDecompose(SurfaceArgs& args);

}  // namespace acdcli
