#include <acd/status.hpp>

namespace acd {

const char* toString(StatusCode code) {
  switch (code) {
    case StatusCode::Ok: return "ok";
    case StatusCode::FileUnreadable: return "file unreadable";
    case StatusCode::UnsupportedFormat: return "unsupported format";
    case StatusCode::EmptyMesh: return "empty mesh";
    case StatusCode::NonFiniteVertex: return "non-finite vertex";
    case StatusCode::IndexOutOfRange: return "face index out of range";
    case StatusCode::DegenerateFace: return "degenerate face";
    case StatusCode::DuplicateFace: return "duplicate face";
    case StatusCode::NonManifoldEdge: return "non-manifold edge";
    case StatusCode::NonManifoldVertex: return "non-manifold vertex";
    case StatusCode::InconsistentOrientation: return "inconsistent orientation";
    case StatusCode::OpenMesh: return "open mesh";
    case StatusCode::InvalidParameter: return "invalid parameter";
    case StatusCode::InternalError: return "internal error";
  }
  return "unknown";
}

}  // namespace acd
