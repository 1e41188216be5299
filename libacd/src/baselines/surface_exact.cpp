// Flood-and-retract: patches grow from seed faces across edges, flattest neighbour first. A face
// joins only if the patch stays on the boundary of its own hull: the face's plane must have every
// patch vertex on one side, and its new vertices must lie on the known side of every plane of the
// patch. A face that would break this is retracted from the patch's front and waits for a later
// seed. Adding faces only adds constraints, so a retracted face never fits the same patch later.
#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/surface_exact.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <string>
#include <unordered_map>

namespace acd {

namespace {

// A face's plane as a unit normal and a point on it (a corner of the face): distances are taken
// from that corner, not from the origin, so that a model far from the origin loses no precision.
// Not acd::Plane or acd::HalfSpace (normal . x = offset): their offset form measures from the
// origin, and would move the tolerance tests that decide the patches in the last bits.
struct AnchoredPlane {
  Vec3 normal = Vec3::Zero();  // unit; zero for a degenerate face
  Vec3 anchor = Vec3::Zero();
  double distance(const Vec3& v) const { return normal.dot(v - anchor); }
};

// Faces with (numerically) no area have no plane; they join patches on their vertices alone.
double degenerateArea2(const TriMesh& mesh) {
  const double diag = boundingBox(mesh).size().norm();
  return 1e-28 * diag * diag * diag * diag;  // |cross|^2 below (1e-14 diag^2)^2
}

AnchoredPlane facePlane(const TriMesh& mesh, int f, double degenerate2) {
  const Vec3 n = faceNormal(mesh, f);
  AnchoredPlane p;
  if (n.squaredNorm() <= degenerate2) return p;
  p.normal = n.normalized();
  p.anchor = mesh.vertices[mesh.faces[f][0]];
  return p;
}

bool degenerate(const AnchoredPlane& p) { return p.normal.isZero(); }

// Which side of a plane the patch lies on: -1 behind, +1 in front, 0 not yet known (all on it).
int sideOf(double distance, double tol) { return distance > tol ? 1 : (distance < -tol ? -1 : 0); }

class PatchGrower {
 public:
  PatchGrower(const TriMesh& mesh, double tol)
      : mesh_(mesh), tol_(tol), planes_(mesh.faces.size()), vertexStamp_(mesh.vertices.size(), -1),
        rejectStamp_(mesh.faces.size(), -1) {
    const double d2 = degenerateArea2(mesh);
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
      planes_[f] = facePlane(mesh, f, d2);
      for (int k = 0; k < 3; ++k) edgeFaces_[edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3])].push_back(f);
    }
  }

  std::vector<int> patchOfFace() {
    const int n = static_cast<int>(mesh_.faces.size());
    std::vector<int> owner(n, -1);
    // Seeds by decreasing area: big flat regions become one patch before their rim is taken.
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> area(n);
    for (int f = 0; f < n; ++f) area[f] = faceNormal(mesh_, f).squaredNorm();
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
    int patch = 0;
    for (int seed : order)
      if (owner[seed] < 0) grow(seed, patch++, owner);
    return owner;
  }

 private:
  struct PatchPlane {
    int face;   // whose plane it is
    int side;   // see sideOf
  };
  struct Candidate {
    double turn;  // 1 - cos of the angle to the face it was reached from: flattest first
    int face, from;
    bool operator<(const Candidate& o) const { return turn != o.turn ? turn > o.turn : face > o.face; }
  };

  void grow(int seed, int patch, std::vector<int>& owner) {
    vertices_.clear();
    planes_in_.clear();
    std::priority_queue<Candidate> front;
    front.push({0.0, seed, -1});
    while (!front.empty()) {
      const Candidate c = front.top();
      front.pop();
      if (owner[c.face] >= 0 || rejectStamp_[c.face] == patch) continue;
      if (!tryAdd(c.face, c.from, patch)) {
        rejectStamp_[c.face] = patch;  // retracted: constraints only grow, it will not fit later
        continue;
      }
      owner[c.face] = patch;
      const Face& t = mesh_.faces[c.face];
      for (int k = 0; k < 3; ++k) {
        for (int g : edgeFaces_[edgeKey(t[k], t[(k + 1) % 3])]) {
          if (g == c.face || owner[g] >= 0 || rejectStamp_[g] == patch) continue;
          const AnchoredPlane &a = planes_[c.face], &b = planes_[g];
          const double turn = degenerate(a) || degenerate(b) ? 1.0 : 1.0 - a.normal.dot(b.normal);
          front.push({turn, g, c.face});
        }
      }
    }
  }

  double distance(int face, int vertex) const {
    return planes_[face].distance(mesh_.vertices[vertex]);
  }

  bool tryAdd(int face, int from, int patch) {
    const Face& t = mesh_.faces[face];
    int fresh[3], nFresh = 0;
    for (int v : t)
      if (vertexStamp_[v] != patch && std::find(fresh, fresh + nFresh, v) == fresh + nFresh) fresh[nFresh++] = v;

    // The new vertices against the planes the patch already has.
    std::vector<std::pair<std::size_t, int>> sideUpdates;
    for (std::size_t i = 0; i < planes_in_.size(); ++i) {
      int side = planes_in_[i].side;
      for (int k = 0; k < nFresh; ++k) {
        const int s = sideOf(distance(planes_in_[i].face, fresh[k]), tol_);
        if (s == 0) continue;
        if (side == 0) side = s;
        else if (s != side) return false;
      }
      if (side != planes_in_[i].side) sideUpdates.emplace_back(i, side);
    }

    // The face's own plane against every vertex of the patch (unless it is the plane of the face
    // it was reached from, up to rounding: then the checks above already cover it).
    const AnchoredPlane& own = planes_[face];
    bool newPlane = !degenerate(own);
    int ownSide = 0;
    if (newPlane && from >= 0) {
      const AnchoredPlane& prev = planes_[from];
      bool same = !degenerate(prev) && (own.normal - prev.normal).norm() < 1e-12;
      for (int k = 0; same && k < 3; ++k) same = std::abs(prev.distance(mesh_.vertices[t[k]])) < 1e-3 * tol_;
      newPlane = !same;
    }
    if (newPlane) {
      for (int v : vertices_) {
        const int s = sideOf(distance(face, v), tol_);
        if (s == 0) continue;
        if (ownSide == 0) ownSide = s;
        else if (s != ownSide) return false;
      }
    }

    for (const auto& [i, side] : sideUpdates) planes_in_[i].side = side;
    if (newPlane) planes_in_.push_back({face, ownSide});
    for (int k = 0; k < nFresh; ++k) {
      vertexStamp_[fresh[k]] = patch;
      vertices_.push_back(fresh[k]);
    }
    return true;
  }

  const TriMesh& mesh_;
  double tol_;
  std::vector<AnchoredPlane> planes_;                                  // per face
  std::unordered_map<std::uint64_t, std::vector<int>> edgeFaces_;
  std::vector<int> vertexStamp_;  // vertex -> patch it was last added to
  std::vector<int> rejectStamp_;  // face -> patch that retracted it last
  std::vector<int> vertices_;     // of the growing patch
  std::vector<PatchPlane> planes_in_;  // distinct planes of the growing patch
};

Status checkInput(const TriMesh& mesh) {
  if (mesh.faces.empty()) return Status::error(StatusCode::EmptyMesh, "mesh has no faces");
  const int nv = static_cast<int>(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite())
      return Status::error(StatusCode::NonFiniteVertex, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= nv)
        return Status::error(StatusCode::IndexOutOfRange, "face " + std::to_string(f) + " refers to vertex " +
                                                              std::to_string(v) + " but the mesh has " +
                                                              std::to_string(nv) + " vertices");
  return Status::success();
}

}  // namespace

SurfaceExactDecomposition exactSurfaceDecomposition(const TriMesh& mesh, const SurfaceExactOptions& options) {
  const auto start = acd::Clock::now();
  SurfaceExactDecomposition out;
  if (!(options.tolerance >= 0.0) || !std::isfinite(options.tolerance)) {
    out.status = Status::error(StatusCode::InvalidParameter, "tolerance must be a finite number >= 0");
    return out;
  }
  out.status = checkInput(mesh);
  if (!out.status.ok()) return out;
  const double scale = minimumSphereNormalization(compact(mesh)).scale;
  PatchGrower grower(mesh, options.tolerance / scale);
  out.patchOfFace = grower.patchOfFace();
  int count = 0;
  for (int p : out.patchOfFace) count = std::max(count, p + 1);
  out.patches.resize(count);
  for (int f = 0; f < static_cast<int>(out.patchOfFace.size()); ++f) out.patches[out.patchOfFace[f]].push_back(f);
  out.seconds = acd::secondsSince(start);
  return out;
}

bool isConvexPatch(const TriMesh& mesh, const std::vector<int>& faces, double tolerance) {
  std::vector<int> vertices;
  for (int f : faces) vertices.insert(vertices.end(), mesh.faces[f].begin(), mesh.faces[f].end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  const double d2 = degenerateArea2(mesh);
  for (int f : faces) {
    const AnchoredPlane p = facePlane(mesh, f, d2);
    if (degenerate(p)) continue;
    bool front = false, behind = false;
    for (int v : vertices) {
      const double d = p.distance(mesh.vertices[v]);
      front |= d > tolerance;
      behind |= d < -tolerance;
    }
    if (front && behind) return false;
  }
  return true;
}

TriMesh patchMesh(const TriMesh& mesh, const std::vector<int>& faces) {
  TriMesh out;
  out.vertices = mesh.vertices;
  out.faces.reserve(faces.size());
  for (int f : faces) out.faces.push_back(mesh.faces[f]);
  return compact(out);
}

}  // namespace acd
