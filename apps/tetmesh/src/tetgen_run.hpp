// TetGen 1.5, called as a library but in a separate process.
//
// Why a process: after any error it detects in its input, TetGen 1.5 throws having already
// freed its memory, and the tetgenio destructors free it again, so the caller crashes. The
// call therefore runs in a fork()ed child that sends the mesh back through a pipe; a TetGen
// error, crash or hang ends as a message here, never as a crash of the caller.
#pragma once

#include "tet_mesh.hpp"

#include <string>

namespace tetmesh {

struct TetGenOptions {
  double radiusEdge = 2.0;   // TetGen `q` bound on circumradius / shortest edge; <= 0: no quality refinement
  double minDihedral = 0.0;  // TetGen `q` second value in degrees; 0: TetGen's default
  double maxVolume = 0.0;    // TetGen `a`; <= 0: no bound
  bool regions = true;       // `A`: label tets by the region seeds of the PLC
  bool checkIntersections = false;  // `d` only: report intersecting facets and stop
  int timeoutSeconds = 120;  // the child is stopped after this (TetGen can loop on near-degenerate input)
};

struct TetGenResult {
  bool ok = false;
  std::string error;      // one line: what TetGen said, or how the child ended
  std::string switches;   // exactly what TetGen was given
  TetMesh mesh;           // tets oriented to positive volume
  double seconds = 0.0;   // wall time of the child
};

/// TetGen switches for these options, e.g. "pq2/0AQz".
std::string tetgenSwitches(const TetGenOptions& options);

/// Meshes the PLC. Never throws and never crashes on bad input; see `error`.
TetGenResult runTetGen(const Plc& plc, const TetGenOptions& options);

}  // namespace tetmesh
