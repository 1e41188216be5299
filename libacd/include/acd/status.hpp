// Status: data errors are values, not exceptions (see docs/ERRORS.md).
#pragma once

#include <string>

namespace acd {

enum class StatusCode {
  Ok = 0,
  FileUnreadable,      // cannot open or parse the file
  UnsupportedFormat,   // extension not OFF/OBJ/PLY/STL
  EmptyMesh,           // no faces
  NonFiniteVertex,     // NaN or infinite coordinate
  IndexOutOfRange,     // face refers to a vertex that does not exist
  DegenerateFace,      // zero area or repeated vertex
  DuplicateFace,       // same vertex set twice
  NonManifoldEdge,     // edge shared by more than two faces
  NonManifoldVertex,   // vertex whose faces form more than one fan
  InconsistentOrientation,
  OpenMesh,            // boundary edges
  InvalidParameter,    // tau <= 0, NaN, absurd values
  InternalError,       // a bug: an invariant did not hold
};

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;  // one line, names the offending element where there is one

  bool ok() const { return code == StatusCode::Ok; }
  static Status success() { return {}; }
  static Status error(StatusCode c, std::string msg) { return {c, std::move(msg)}; }
};

const char* toString(StatusCode code);

}  // namespace acd
