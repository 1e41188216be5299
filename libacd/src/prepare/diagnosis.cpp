// Mesh diagnosis and the safe repairs before solid decomposition. Both walk the
// same checks in the same order, so `acd info` names the problem that
// prepareSolid() would refuse or repair first.
#include <acd/algo/face_order.hpp>
#include <acd/algo/hole_filling.hpp>
#include <acd/algo/union_find.hpp>
#include <acd/diagnosis.hpp>

#include <algorithm>
#include <unordered_map>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>

namespace acd {
namespace {

/// Below this fraction of the squared bounding-box diagonal a triangle has no usable normal.
constexpr double kZeroAreaFraction = 1e-14;

bool isFinite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::string formatPoint(const Vec3& p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return s.str();
}

std::string formatFace(const Face& f) {
  return "(vertices " + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + ")";
}

std::string formatEdge(std::uint64_t key) {
  return std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu);
}

bool hasRepeatedIndex(const Face& f) { return f[0] == f[1] || f[1] == f[2] || f[2] == f[0]; }

bool indicesInRange(const Face& f, int vertexCount) {
  return std::all_of(f.begin(), f.end(), [&](int v) { return v >= 0 && v < vertexCount; });
}

double squaredDiagonal(const Box3& box) { return box.size().squaredNorm(); }


/// Bounding box of the finite vertices only: one NaN must not poison the scale of every test.
Box3 finiteBoundingBox(const std::vector<Vec3>& vertices) {
  Box3 box;
  bool first = true;
  for (const Vec3& p : vertices) {
    if (!isFinite(p)) continue;
    box.lo = first ? p : Vec3(box.lo.cwiseMin(p));
    box.hi = first ? p : Vec3(box.hi.cwiseMax(p));
    first = false;
  }
  return box;
}

/// Faces grouped by vertex set: each group lists face positions in increasing order.
/// Returns, per face, the first face with the same vertex set (itself when it is the first).
std::vector<int> firstWithSameVertices(const std::vector<Face>& faces) {
  struct Keyed {
    Face sorted;
    int face;
    bool operator<(const Keyed& o) const { return sorted != o.sorted ? sorted < o.sorted : face < o.face; }
  };
  std::vector<Keyed> keyed(faces.size());
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    keyed[f] = {faces[f], f};
    std::sort(keyed[f].sorted.begin(), keyed[f].sorted.end());
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> first(faces.size());
  for (size_t i = 0; i < keyed.size(); ++i)
    first[keyed[i].face] = i > 0 && keyed[i].sorted == keyed[i - 1].sorted ? first[keyed[i - 1].face] : keyed[i].face;
  return first;
}

/// A corner is (face, position) numbered 3 * face + position; the half-edge of a corner runs
/// from its vertex to the next vertex of the face.
int nextCorner(int corner) { return corner - corner % 3 + (corner % 3 + 1) % 3; }

/// How faces use one undirected edge.
struct EdgeUse {
  std::uint64_t key = 0;
  int count = 0;
  int forward = 0;             // uses from the lower to the higher vertex index
  int corners[2] = {-1, -1};   // the first two half-edges: enough for manifold edges
};

/// Edges, faces per edge and edge-connected components of a face list with valid indices.
struct Topology {
  std::vector<EdgeUse> edges;       // by key
  std::vector<int> edgeOfCorner;    // -1 where a repeated index makes no edge
  std::vector<int> componentOf;     // per face, numbered in order of first face
  int components = 0;

  explicit Topology(const std::vector<Face>& faces) {
    const int nf = static_cast<int>(faces.size());
    auto vertexAt = [&](int corner) { return faces[corner / 3][corner % 3]; };
    // Numbered by bucket rather than hashed or sorted (acd/mesh.hpp): millions of edges. Corners
    // in order, so each edge's first two uses are its lowest corners.
    const SideEdges numbered = numberEdges(faces);
    edgeOfCorner = numbered.edgeOfSide;
    edges.resize(numbered.edges);
    UnionFind pieces(nf);
    for (int c = 0; c < 3 * nf; ++c) {
      const int id = edgeOfCorner[c];
      if (id < 0) continue;  // a repeated index is a degenerate face, not an edge
      EdgeUse& use = edges[id];
      const int a = vertexAt(c), b = vertexAt(nextCorner(c));
      if (use.count == 0) use.key = edgeKey(a, b);
      if (use.count < 2) use.corners[use.count] = c;
      ++use.count;
      if (a < b) ++use.forward;
      pieces.join(c / 3, use.corners[0] / 3);
    }
    componentOf.assign(nf, -1);
    std::vector<int> idOfRoot(nf, -1);
    for (int f = 0; f < nf; ++f) {
      int& id = idOfRoot[pieces.find(f)];
      if (id < 0) id = components++;
      componentOf[f] = id;
    }
  }
};

/// Number of face fans around each vertex, joining faces across manifold edges only.
/// More than one fan means the surface pinches at the vertex.
std::vector<int> fansPerVertex(const std::vector<Face>& faces, const Topology& topology, int vertexCount,
                               std::vector<int>* fanOfCorner = nullptr) {
  const int corners = static_cast<int>(faces.size()) * 3;
  auto vertexAt = [&](int corner) { return faces[corner / 3][corner % 3]; };
  // Only corners of the same vertex are ever joined, so each set is one fan of one vertex.
  UnionFind fan(corners);
  for (int c = 0; c < corners; ++c)  // corners of one vertex in one degenerate face are one fan
    if (vertexAt(c) == vertexAt(nextCorner(c))) fan.join(c, nextCorner(c));
  for (const EdgeUse& use : topology.edges) {
    if (use.count != 2) continue;
    const int a1 = use.corners[0], b1 = nextCorner(a1);
    const int c2 = use.corners[1], d2 = nextCorner(c2);
    const bool sameDirection = vertexAt(c2) == vertexAt(a1);
    fan.join(a1, sameDirection ? c2 : d2);
    fan.join(b1, sameDirection ? d2 : c2);
  }
  std::vector<int> fans(vertexCount, 0);
  for (int c = 0; c < corners; ++c)
    if (fan.find(c) == c) ++fans[vertexAt(c)];
  if (fanOfCorner) {
    fanOfCorner->resize(corners);
    for (int c = 0; c < corners; ++c) (*fanOfCorner)[c] = fan.find(c);
  }
  return fans;
}

/// The first edge, in face order, whose use satisfies `pick`; -1 if none.
template <class Pick>
int firstEdgeWhere(const Topology& topology, Pick pick) {
  for (int e : topology.edgeOfCorner)
    if (e >= 0 && pick(topology.edges[e])) return e;
  return -1;
}

bool isBoundary(const EdgeUse& u) { return u.count == 1; }
bool isNonManifold(const EdgeUse& u) { return u.count > 2; }
bool isMisoriented(const EdgeUse& u) { return u.count == 2 && u.forward != 1; }

/// Sum over components of (2 - chi) / 2; -1 when a component does not give a whole genus.
int genusOf(const std::vector<Face>& faces, const Topology& topology, int vertexCount) {
  std::vector<long long> chi(topology.components, 0);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) chi[topology.componentOf[f]] += 1;
  for (const EdgeUse& use : topology.edges) chi[topology.componentOf[use.corners[0] / 3]] -= 1;
  // Without non-manifold vertices each vertex belongs to exactly one component.
  std::vector<int> componentOfVertex(vertexCount, -1);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f)
    for (int v : faces[f]) componentOfVertex[v] = topology.componentOf[f];
  for (int c : componentOfVertex)
    if (c >= 0) chi[c] += 1;
  long long genus = 0;
  for (long long x : chi) {
    if (x > 2 || (2 - x) % 2 != 0) return -1;
    genus += (2 - x) / 2;
  }
  return static_cast<int>(genus);
}

std::string outOfRangeMessage(int face, const Face& f, int vertexCount) {
  for (int v : f)
    if (v < 0 || v >= vertexCount)
      return "face " + std::to_string(face) + " refers to vertex " + std::to_string(v) + " but the mesh has " +
             std::to_string(vertexCount) + " vertices";
  return {};
}

/// The edge and vertex checks of diagnose(): boundary, non-manifold and misoriented edges,
/// pinched vertices; `note(order, message)` records the first problem of each kind.
template <class Note>
void checkTopology(const std::vector<Face>& faces, const Topology& topology, const std::vector<int>& original, int nv,
                   MeshDiagnosis& d, const Note& note) {
  d.edges = static_cast<int>(topology.edges.size());
  d.components = topology.components;
  for (const EdgeUse& use : topology.edges) {
    d.boundaryEdges += isBoundary(use);
    d.nonManifoldEdges += isNonManifold(use);
    if (isMisoriented(use)) d.orientationConsistent = false;
  }
  if (const int e = firstEdgeWhere(topology, isNonManifold); e >= 0)
    note(7, "non-manifold edge " + formatEdge(topology.edges[e].key) + " is shared by " +
                std::to_string(topology.edges[e].count) + " faces");
  const std::vector<int> fans = fansPerVertex(faces, topology, nv);
  for (int v = 0; v < nv; ++v)
    if (fans[v] > 1) {
      ++d.nonManifoldVertices;
      note(8, "vertex " + std::to_string(v) + " is non-manifold: its faces form " + std::to_string(fans[v]) +
                  " fans that meet only at this vertex");
    }
  if (const int e = firstEdgeWhere(topology, isBoundary); e >= 0)
    note(9, "boundary edge " + formatEdge(topology.edges[e].key) + " has only one face (" +
                std::to_string(d.boundaryEdges) + " boundary edges)");
  if (const int e = firstEdgeWhere(topology, isMisoriented); e >= 0) {
    const EdgeUse& use = topology.edges[e];
    note(10, "faces " + std::to_string(original[use.corners[0] / 3]) + " and " +
                 std::to_string(original[use.corners[1] / 3]) + " use edge " + formatEdge(use.key) +
                 " in the same direction (inconsistent orientation)");
  }
}

}  // namespace

MeshDiagnosis diagnose(const TriMesh& mesh) {
  MeshDiagnosis d;
  const int nv = static_cast<int>(mesh.vertices.size());
  d.vertices = nv;
  d.faces = static_cast<int>(mesh.faces.size());
  std::vector<std::string> problems(12);  // by check order; the first non-empty one is reported
  auto note = [&](int order, std::string message) {
    if (problems[order].empty()) problems[order] = std::move(message);
  };
  if (mesh.faces.empty()) note(0, "mesh has no faces");

  for (int v = 0; v < nv; ++v)
    if (!isFinite(mesh.vertices[v])) {
      ++d.nonFiniteVertices;
      note(1, "vertex " + std::to_string(v) + " has a non-finite coordinate " + formatPoint(mesh.vertices[v]));
    }
  d.bbox = finiteBoundingBox(mesh.vertices);
  const double squaredDiag = squaredDiagonal(d.bbox);

  // Faces with a bad index cannot take part in anything else.
  std::vector<Face> faces;
  std::vector<int> original;
  faces.reserve(mesh.faces.size());
  original.reserve(mesh.faces.size());
  std::vector<char> referenced(nv, 0);
  for (int f = 0; f < d.faces; ++f) {
    const Face& face = mesh.faces[f];
    if (!indicesInRange(face, nv)) {
      ++d.indexOutOfRange;
      note(2, outOfRangeMessage(f, face, nv));
      continue;
    }
    faces.push_back(face);
    original.push_back(f);
    for (int v : face) referenced[v] = 1;
  }

  const std::vector<int> samePosition = firstAtSamePosition(mesh.vertices);
  for (int v = 0; v < nv; ++v) {
    if (samePosition[v] != v) {
      ++d.duplicateVertices;
      note(3, "vertex " + std::to_string(v) + " has the same position as vertex " + std::to_string(samePosition[v]) +
                  " " + formatPoint(mesh.vertices[v]));
    }
    if (!referenced[v]) {
      ++d.unreferencedVertices;
      note(11, "vertex " + std::to_string(v) + " is not used by any face");
    }
  }

  const std::vector<int> sameVertices = firstWithSameVertices(faces);
  std::vector<Face> finiteFaces;
  finiteFaces.reserve(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    const Face& face = faces[i];
    const int f = original[i];
    const bool finite = isFinite(mesh.vertices[face[0]]) && isFinite(mesh.vertices[face[1]]) &&
                        isFinite(mesh.vertices[face[2]]);
    if (finite) finiteFaces.push_back(face);
    if (hasRepeatedIndex(face)) {
      ++d.degenerateFaces;
      note(4, "face " + std::to_string(f) + " " + formatFace(face) + " repeats a vertex");
    } else if (finite && hasZeroArea(mesh.vertices, face, squaredDiag)) {
      ++d.degenerateFaces;
      note(6, "face " + std::to_string(f) + " " + formatFace(face) + " has zero area");
    }
    if (sameVertices[i] != static_cast<int>(i)) {
      ++d.duplicateFaces;
      note(5, "face " + std::to_string(f) + " " + formatFace(face) + " uses the same vertices as face " +
                  std::to_string(original[sameVertices[i]]));
    }
  }

  const Topology topology(faces);
  checkTopology(faces, topology, original, nv, d, note);

  d.closed = !faces.empty() && d.indexOutOfRange == 0 && d.boundaryEdges == 0 && d.nonManifoldEdges == 0;
  if (d.closed && d.nonManifoldVertices == 0) d.genus = genusOf(faces, topology, nv);

  if (d.nonFiniteVertices == 0 && d.indexOutOfRange == 0) {
    d.volume = signedVolume(mesh);
    d.area = surfaceArea(mesh);
  } else {
    // Measure what can be measured; compact() drops the vertices that would poison the reference point.
    const TriMesh finite = compact(TriMesh{mesh.vertices, finiteFaces});
    d.volume = signedVolume(finite);
    d.area = surfaceArea(finite);
  }

  for (const std::string& p : problems)
    if (!p.empty()) {
      d.firstProblem = p;
      break;
    }
  return d;
}

int countNonManifoldVertices(const std::vector<Face>& faces, int vertexCount) {
  const std::vector<int> fans = fansPerVertex(faces, Topology(faces), vertexCount);
  return static_cast<int>(std::count_if(fans.begin(), fans.end(), [](int n) { return n > 1; }));
}

namespace {

/// An exact copy adds nothing; a copy facing the other way is a two-sided sheet we cannot interpret.
Status dropDuplicateFaces(std::vector<Face>& faces, std::vector<int>& original, std::vector<std::string>& repairs) {
  const std::vector<int> sameVertices = firstWithSameVertices(faces);
  std::vector<Face> unique;
  std::vector<int> uniqueOriginal;
  unique.reserve(faces.size());
  uniqueOriginal.reserve(faces.size());
  int duplicates = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const int first = sameVertices[i];
    if (first == static_cast<int>(i)) {
      unique.push_back(faces[i]);
      uniqueOriginal.push_back(original[i]);
    } else if (sameCyclicOrder(faces[i], faces[first])) {
      ++duplicates;
    } else {
      return Status::error(StatusCode::DuplicateFace, "face " + std::to_string(original[i]) + " " + formatFace(faces[i]) +
                                                          " is face " + std::to_string(original[first]) +
                                                          " with the opposite orientation");
    }
  }
  if (duplicates > 0) repairs.push_back("dropped " + std::to_string(duplicates) + " duplicate faces");
  faces.swap(unique);
  original.swap(uniqueOriginal);
  return Status::success();
}

/// A vertex where several fans meet (two parts touching at a point) is safely split: each fan
/// after the first gets its own copy of the vertex, at the same position.
void splitPinchedVertices(std::vector<Face>& faces, const Topology& topology, int nv, std::vector<Vec3>& vertices,
                          std::vector<std::string>& repairs) {
  std::vector<int> fanOfCorner;
  const std::vector<int> fans = fansPerVertex(faces, topology, nv, &fanOfCorner);
  std::unordered_map<int, int> copyOfFan;  // fan root corner -> vertex
  std::vector<int> firstFan(nv, -1);
  int split = 0;
  for (int c = 0; c < static_cast<int>(fanOfCorner.size()); ++c) {
    int& v = faces[c / 3][c % 3];
    if (fans[v] <= 1) continue;
    const int fan = fanOfCorner[c];
    if (firstFan[v] < 0) firstFan[v] = fan;
    if (firstFan[v] == fan) continue;
    auto [it, inserted] = copyOfFan.emplace(fan, static_cast<int>(vertices.size()));
    if (inserted) {
      vertices.push_back(vertices[v]);
      ++split;
    }
    v = it->second;
  }
  if (split > 0)
    repairs.push_back("split " + std::to_string(split) +
                      " non-manifold vertices (parts touching at a point) into one copy per fan");
}

/// Orient each component by breadth-first search across its (now all manifold) edges.
Status orientConsistently(std::vector<Face>& faces, const Topology& topology, const std::vector<int>& original,
                          std::vector<std::string>& repairs) {
  const int nf = static_cast<int>(faces.size());
  std::vector<signed char> flip(nf, -1);  // -1: not reached yet
  int flipped = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<int> members{seed};
    flip[seed] = 0;
    for (size_t next = 0; next < members.size(); ++next) {
      const int f = members[next];
      for (int corner = 3 * f; corner < 3 * f + 3; ++corner) {
        const EdgeUse& use = topology.edges[topology.edgeOfCorner[corner]];
        if (use.count < 2) continue;  // a boundary edge has no face across
        const int g = (use.corners[0] == corner ? use.corners[1] : use.corners[0]) / 3;
        // Both faces running the edge the same way means exactly one of them must turn.
        const signed char wanted = static_cast<signed char>(flip[f] ^ (use.forward != 1));
        if (flip[g] < 0) {
          flip[g] = wanted;
          members.push_back(g);
        } else if (flip[g] != wanted) {
          return Status::error(StatusCode::InconsistentOrientation,
                        "faces " + std::to_string(original[f]) + " and " + std::to_string(original[g]) +
                            " cannot be oriented consistently: the piece containing face " +
                            std::to_string(original[seed]) + " is non-orientable");
        }
      }
    }
    // Turn the minority: the outward step below fixes the direction of the whole piece anyway.
    const int count = static_cast<int>(std::count_if(members.begin(), members.end(), [&](int f) { return flip[f]; }));
    const bool invert = 2 * count > static_cast<int>(members.size());
    for (int f : members) {
      if (invert) flip[f] = !flip[f];
      if (flip[f]) {
        std::swap(faces[f][1], faces[f][2]);
        ++flipped;
      }
    }
  }
  if (flipped > 0)
    repairs.push_back("flipped " + std::to_string(flipped) + " faces to make the orientation consistent");
  return Status::success();
}

/// Closes every open piece with filled holes (the solid decomposition needs closed pieces).
Status fillOpenPieces(std::vector<TriMesh>& pieces, int& holesFilled, std::vector<std::string>& repairs) {
  int addedFaces = 0;
  for (TriMesh& piece : pieces) {
    if (isClosedOriented(piece)) continue;
    const int before = static_cast<int>(piece.faces.size());
    HoleFilling filled = fillHoles(piece);
    if (!filled.status.ok())
      return Status::error(StatusCode::OpenMesh, "open mesh: " + filled.status.message + "; solid decomposition needs a closed mesh (surface decomposition works on the open mesh)");
    holesFilled += filled.holes;
    addedFaces += static_cast<int>(filled.mesh.faces.size()) - before;
    piece = std::move(filled.mesh);
  }
  repairs.push_back("filled " + std::to_string(holesFilled) + (holesFilled == 1 ? " hole" : " holes") +
                        " (" + std::to_string(addedFaces) + " faces added) to close the open mesh");
  return Status::success();
}

/// Closed pieces turned outward where they were inside out, each checked closed and oriented.
Status turnOutward(std::vector<TriMesh>& pieces, std::vector<std::string>& repairs) {
  int reversed = 0;
  for (TriMesh& piece : pieces) {
    if (signedVolume(piece) < 0.0) {
      for (Face& f : piece.faces) std::swap(f[1], f[2]);
      ++reversed;
    }
    if (!isClosedOriented(piece))
      return Status::error(StatusCode::InternalError, "a repaired component is not closed and consistently oriented");
  }
  if (reversed > 0)
    repairs.push_back(pieces.size() == 1 ? std::string("reversed all faces: the mesh was inside out")
                                         : "reversed " + std::to_string(reversed) + " of " +
                                               std::to_string(pieces.size()) + " components that were inside out");
  if (pieces.size() > 1)
    repairs.push_back("split into " + std::to_string(pieces.size()) + " components, decomposed separately");
  return Status::success();
}

}  // namespace

PreparedSolid prepareSolid(const TriMesh& mesh, const PrepareOptions& options) {
  PreparedSolid out;
  auto refuse = [&](StatusCode code, std::string message) {
    out.status = Status::error(code, std::move(message));
    out.components.clear();
    return out;
  };
  const int nv = static_cast<int>(mesh.vertices.size());
  if (mesh.faces.empty()) return refuse(StatusCode::EmptyMesh, "mesh has no faces");
  for (int v = 0; v < nv; ++v)
    if (!isFinite(mesh.vertices[v]))
      return refuse(StatusCode::NonFiniteVertex,
                    "vertex " + std::to_string(v) + " has a non-finite coordinate " + formatPoint(mesh.vertices[v]));
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
    if (!indicesInRange(mesh.faces[f], nv))
      return refuse(StatusCode::IndexOutOfRange, outOfRangeMessage(f, mesh.faces[f], nv));

  // Known clean and closed, with no zero-area face (its own test), the steps below would give the
  // mesh back as it is (a tenth of a dense scan's set-up): only a piece too small to close a
  // solid (a face and its reverse, which they drop) still takes them.
  if (options.knownClean && isClosedOriented(mesh) && firstZeroAreaFace(mesh) < 0) {
    std::vector<TriMesh> pieces = splitEdgeConnected(mesh);
    if (std::all_of(pieces.begin(), pieces.end(), [](const TriMesh& p) { return p.faces.size() >= 4; })) {
      if (Status s = turnOutward(pieces, out.repairs); !s.ok()) return refuse(s.code, s.message);
      out.components = std::move(pieces);
      out.status = Status::success();
      return out;
    }
  }

  // Messages name the caller's face numbers, so keep them through the repairs.
  std::vector<Face> faces;
  std::vector<int> original;
  faces.reserve(mesh.faces.size());
  original.reserve(mesh.faces.size());

  std::vector<char> referenced(nv, 0);
  for (const Face& f : mesh.faces)
    for (int v : f) referenced[v] = 1;
  const int unreferenced = static_cast<int>(std::count(referenced.begin(), referenced.end(), 0));

  // Merge vertices at exactly the same position onto the first one (STL-like input).
  const std::vector<int> samePosition = firstAtSamePosition(mesh.vertices);
  int merged = 0;
  for (int v = 0; v < nv; ++v) merged += referenced[v] && samePosition[v] != v;
  if (merged > 0)
    out.repairs.push_back("merged " + std::to_string(merged) + " vertices with the same position as an earlier vertex");

  int repeated = 0;
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    Face face = mesh.faces[f];
    for (int& v : face) v = samePosition[v];
    if (hasRepeatedIndex(face)) {
      ++repeated;
      continue;
    }
    faces.push_back(face);
    original.push_back(f);
  }
  if (repeated > 0)
    out.repairs.push_back("dropped " + std::to_string(repeated) + " faces with a repeated vertex");

  if (Status s = dropDuplicateFaces(faces, original, out.repairs); !s.ok()) return refuse(s.code, s.message);
  if (faces.empty()) return refuse(StatusCode::EmptyMesh, "mesh has no faces left after dropping degenerate faces");

  const double squaredDiag = squaredDiagonal(boundingBox(mesh));
  for (size_t i = 0; i < faces.size(); ++i)
    if (hasZeroArea(mesh.vertices, faces[i], squaredDiag))
      return refuse(StatusCode::DegenerateFace,
                    "face " + std::to_string(original[i]) + " " + formatFace(faces[i]) + " has zero area");

  const Topology topology(faces);
  if (const int e = firstEdgeWhere(topology, isNonManifold); e >= 0)
    return refuse(StatusCode::NonManifoldEdge, "non-manifold edge " + formatEdge(topology.edges[e].key) +
                                                   " is shared by " + std::to_string(topology.edges[e].count) +
                                                   " faces");
  std::vector<Vec3> vertices = mesh.vertices;
  splitPinchedVertices(faces, topology, nv, vertices, out.repairs);
  const bool open = firstEdgeWhere(topology, isBoundary) >= 0;
  if (open && options.openMeshes == OpenMeshPolicy::Refuse) {
    const int e = firstEdgeWhere(topology, isBoundary);
    const auto boundary = std::count_if(topology.edges.begin(), topology.edges.end(), isBoundary);
    return refuse(StatusCode::OpenMesh, "open mesh: " + std::to_string(boundary) + " boundary edges (first: vertices " +
                                            formatEdge(topology.edges[e].key) +
                                            "); solid decomposition needs a closed mesh");
  }

  if (Status s = orientConsistently(faces, topology, original, out.repairs); !s.ok()) return refuse(s.code, s.message);

  std::vector<TriMesh> pieces = splitEdgeConnected(TriMesh{vertices, faces});
  if (open && options.openMeshes == OpenMeshPolicy::KeepOpen) {
    // Surfaces keep their holes; an open piece has no inside, so its orientation stays as found
    // (surface ACD turns it so that it faces its hull; see acd/surface_decompose.hpp).
    for (TriMesh& piece : pieces)
      if (isClosedOriented(piece) && signedVolume(piece) < 0.0)
        for (Face& f : piece.faces) std::swap(f[1], f[2]);
    if (unreferenced > 0)
      out.repairs.push_back("dropped " + std::to_string(unreferenced) + " vertices not used by any face");
    out.components = std::move(pieces);
    out.status = Status::success();
    return out;
  }
  if (open)
    if (Status s = fillOpenPieces(pieces, out.holesFilled, out.repairs); !s.ok()) return refuse(s.code, s.message);
  if (Status s = turnOutward(pieces, out.repairs); !s.ok()) return refuse(s.code, s.message);
  if (unreferenced > 0)
    out.repairs.push_back("dropped " + std::to_string(unreferenced) + " vertices not used by any face");
  out.components = std::move(pieces);
  out.status = Status::success();
  return out;
}

bool hasZeroArea(const std::vector<Vec3>& vertices, const Face& f, double squaredDiagonal) {
  const Vec3 twiceArea = (vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]);
  return 0.5 * twiceArea.norm() <= kZeroAreaFraction * squaredDiagonal;
}

int firstZeroAreaFace(const TriMesh& mesh) {
  const double squaredDiag = squaredDiagonal(boundingBox(mesh));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (hasZeroArea(mesh.vertices, mesh.faces[f], squaredDiag)) return static_cast<int>(f);
  return -1;
}

}  // namespace acd
