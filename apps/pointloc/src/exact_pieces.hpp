// The solid exact convex decomposition (ECD) of the model, for --compare, when libacd has one.
#pragma once

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace pointloc {

struct ExactPieces {
  bool available = false;         // libacd provides an exact solid decomposition
  bool refused = false;           // the ECD does not accept this model (e.g. self-intersecting)
  bool finished = false;          // the decomposition completed: the pieces cover the model
  std::vector<acd::TriMesh> pieces;
  std::size_t pieceCount = 0;     // as reported, also when unfinished
  double seconds = 0.0;
  std::string note;               // why not available or not finished
};

/// Runs libacd's solid ECD with a time limit, or says that libacd has none.
ExactPieces exactPieces(const acd::TriMesh& model, double timeLimitSeconds);

}  // namespace pointloc
