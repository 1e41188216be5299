#include "exact_pieces.hpp"

#if __has_include(<sandbox/exact_solid.hpp>)
#include <sandbox/exact_solid.hpp>
#define POINTLOC_HAVE_ECD 1
#endif

namespace pointloc {

#ifdef POINTLOC_HAVE_ECD

ExactPieces exactPieces(const acd::TriMesh& model, double timeLimitSeconds) {
  ExactPieces out;
  out.available = true;
  acd::ExactOptions options;
  options.timeLimitSeconds = timeLimitSeconds;
  // No cap on the count: a partial set of pieces would leave holes in the union (the time
  // and memory caps still stop a decomposition that grows too large).
  options.maxPieces = static_cast<std::size_t>(-1);
  acd::ExactDecomposition ecd = acdsandbox::exactSolidDecomposition(model, options);
  out.seconds = ecd.seconds;
  out.pieceCount = ecd.pieceCount;
  out.refused = !ecd.status.ok();
  out.finished = !out.refused && ecd.finished;
  out.note = out.refused ? ecd.status.message : ecd.note;
  if (out.finished) out.pieces = std::move(ecd.pieces);
  return out;
}

#else

ExactPieces exactPieces(const acd::TriMesh&, double) {
  ExactPieces out;
  out.note = "not available: this libacd has no solid exact convex decomposition";
  return out;
}

#endif

}  // namespace pointloc
