#include "solid_obstacles.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/algo/union_find.hpp>
#include <acd/algo/alpha_wrap.hpp>
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <array>
#include <map>
#include <numeric>
#include <sstream>

namespace planner {

namespace {

/// Faces grouped by vertex-connectivity, corners at identical positions counted as one.
std::vector<acd::TriMesh> vertexConnectedPieces(const acd::TriMesh& m) {
  std::map<std::array<double, 3>, int> byPosition;
  std::vector<int> id(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const acd::Vec3& p = m.vertices[v];
    id[v] = byPosition.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<int>(byPosition.size())).first->second;
  }
  acd::UnionFind sets(static_cast<int>(byPosition.size()));
  for (const acd::Face& f : m.faces)
    for (int k = 1; k < 3; ++k) sets.join(id[f[k]], id[f[0]]);
  std::map<int, acd::TriMesh> pieces;
  std::map<int, std::map<int, int>> localIndex;  // per piece: position id -> vertex of the piece
  for (const acd::Face& f : m.faces) {
    const int root = sets.find(id[f[0]]);
    acd::TriMesh& piece = pieces[root];
    std::map<int, int>& local = localIndex[root];
    acd::Face face{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = local.emplace(id[f[k]], static_cast<int>(piece.vertices.size()));
      if (added) piece.vertices.push_back(m.vertices[f[k]]);
      face[k] = it->second;
    }
    piece.faces.push_back(face);
  }
  std::vector<acd::TriMesh> out;
  for (auto& [root, piece] : pieces) out.push_back(std::move(piece));
  return out;
}

enum class Closing { AsGiven, Repaired, No };

/// The piece as closed solids when repairs make it one without losing surface: a face and its
/// reverse that close nothing (a zero-thickness double-sided wall) are dropped by the repair,
/// so such a piece must be wrapped instead.
Closing closeByRepair(const acd::TriMesh& piece, std::vector<acd::TriMesh>& solids) {
  const acd::MeshRepair repaired = acd::repairMesh(piece);
  if (!repaired.status.ok() || repaired.doubleSidedDroppedBoth > 0 || repaired.leftDegenerateFaces > 0) return Closing::No;
  const acd::PreparedSolid prepared = acd::prepareSolid(repaired.mesh, {acd::OpenMeshPolicy::Refuse});
  if (!prepared.status.ok()) return Closing::No;
  for (const acd::TriMesh& c : prepared.components) {
    const acd::Box3 b = acd::boundingBox(c);
    const double size = b.size().norm();
    // A flat "solid" (two coincident sheets) bounds no volume; the Boolean needs one.
    if (acd::signedVolume(c) <= 1e-9 * size * size * size) return Closing::No;
    if (acd::countSelfIntersections(c, 1) > 0) return Closing::No;
  }
  solids = prepared.components;
  const bool untouched = repaired.repairs.empty() && prepared.repairs.empty();
  return untouched ? Closing::AsGiven : Closing::Repaired;
}

}  // namespace

std::string SolidObstacle::summary() const {
  std::ostringstream s;
  s << soupPieces << (soupPieces == 1 ? " piece: " : " pieces: ") << closedPieces << " closed, " << repairedPieces
    << " repaired, " << wrappedPieces << " wrapped";
  if (wrappedPieces > 0) s << " (alpha " << wrap.alpha << ", offset " << wrap.offset << ", " << wrapFaces << " faces)";
  return s.str();
}

SolidObstacle solidify(const acd::TriMesh& triangles, const WrapSettings& wrap) {
  const auto t0 = acd::Clock::now();
  SolidObstacle out;
  const std::vector<acd::TriMesh> pieces = vertexConnectedPieces(triangles);
  out.soupPieces = static_cast<int>(pieces.size());
  std::vector<acd::TriMesh> toWrap;
  for (const acd::TriMesh& piece : pieces) {
    std::vector<acd::TriMesh> solids;
    switch (closeByRepair(piece, solids)) {
      case Closing::AsGiven: ++out.closedPieces; break;
      case Closing::Repaired: ++out.repairedPieces; break;
      case Closing::No: toWrap.push_back(piece); continue;
    }
    out.pieces.insert(out.pieces.end(), solids.begin(), solids.end());
  }
  out.ok = true;
  if (!toWrap.empty()) {
    out.wrappedPieces = static_cast<int>(toWrap.size());
    out.wrap = wrap;
    const acd::Wrap w = acd::alphaWrap(acd::concatenate(toWrap), wrap.alpha, wrap.offset);
    if (!w.status.ok() || w.mesh.empty()) {
      out.ok = false;
      out.error = "the alpha wrap failed: " + (w.status.ok() ? std::string("empty wrap") : w.status.message);
    } else {
      out.wrapFaces = static_cast<int>(w.mesh.faces.size());
      out.pieces.push_back(w.mesh);
    }
  }
  out.seconds = acd::secondsSince(t0);
  return out;
}

acd::TriMesh concatenatedPieces(const SolidObstacle& solid) { return acd::concatenate(solid.pieces); }

std::vector<acd::Vec3> pieceProbes(const acd::TriMesh& triangles) {
  std::vector<acd::Vec3> probes;
  for (const acd::TriMesh& piece : vertexConnectedPieces(triangles)) probes.push_back(piece.vertices.front());
  return probes;
}

}  // namespace planner
