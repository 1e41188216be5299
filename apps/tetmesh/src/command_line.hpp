// tetmesh's options as given on the command line, and their checks before any work.
#pragma once

#include "deformation_demo.hpp"
#include "hull_mesher.hpp"
#include "tet_files.hpp"

#include <appcli/console.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace tetmesh {

/// "tetmesh: ..." on stderr.
inline const appcli::Console kConsole{"tetmesh"};

/// Deformation demo (--deform): the model's surface embedded in the hull mesh and carried
/// along by an as-rigid-as-possible deformation that moves one component (docs/TETMESH.md).
struct DeformArgs {
  std::string dir;              // empty: no deformation
  int handle = 0, anchor = 0;   // component labels; 0: automatic
  std::vector<double> move;     // dx, dy, dz
  double angle = NAN;           // degrees
  int iterations = ArapOptions{}.maxIterations;
  double minWeight = ArapOptions{}.minWeight;
};

struct Args {
  std::string model;
  HullMeshOptions options;
  std::string mesher = "auto";  // auto, refine or complex
  std::string out;
  std::string format;
  std::string json;
  std::string poly;
  std::string regions;
  bool compare = false;
  bool quiet = false;
  DeformArgs deform;
};

/// The output format from --format, else from the -o extension, and the mesher from --mesher
/// (into `a.options`); kOk or kBadParameter after a message, as for every range checked here.
int checkArgs(Args& a, TetFormat& format);

/// The deformation options as given; kOk, or kBadParameter after a message when they cannot work.
int deformOptions(const DeformArgs& d, DeformationOptions& o);

}  // namespace tetmesh
