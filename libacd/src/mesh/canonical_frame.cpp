// Canonical frame from the surface's moments (they integrate the whole surface, so a few ulps of
// rounding in any vertex move the frame by a few ulps only), then rounding to a grid that absorbs
// those ulps, then an order of vertices and faces that depends on coordinates only.
#include <acd/algo/canonical_frame.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <complex>
#include <cstring>
#include <limits>
#include <cmath>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace acd {

namespace {

/// ∫ (e·x)^3 dA over a triangle whose corners project to p1, p2, p3 on e: A/10 times the complete
/// homogeneous cubic h3(p1, p2, p3) (from ∫ λ^α dA = 2A α! / (|α|+2)!).
double thirdMoment(double area, double p1, double p2, double p3) {
  const double h3 = p1 * p1 * p1 + p2 * p2 * p2 + p3 * p3 * p3 + p1 * p1 * (p2 + p3) + p2 * p2 * (p1 + p3) +
                    p3 * p3 * (p1 + p2) + p1 * p2 * p3;
  return area / 10.0 * h3;
}

double roundToGrid(double x) { return std::nearbyint(x / kCanonicalGrid) * kCanonicalGrid; }

bool lexLess(const Vec3& a, const Vec3& b) {
  return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
}

/// A face's unit normal and area (in the sphere's units).
struct WeightedNormal {
  Vec3 normal;
  double area;
};

/// How much of the surface faces direction d: sum of area * (n.d)^4, largest along a box's axes.
double alignment(const std::vector<WeightedNormal>& normals, const Vec3& d) {
  double sum = 0.0;
  for (const WeightedNormal& w : normals) {
    const double c = w.normal.dot(d);
    sum += w.area * c * c * c * c;
  }
  return sum;
}

/// The directions in the plane of the orthonormal a, b fixed by how the faces' normals spread in
/// it: with u = p + iq a normal's coordinates in the plane, the first angular harmonic
/// Z_k = sum A |u|^2 (u/|u|)^k (k = 1, 2, ...) that does not vanish gives theta = arg(Z_k) / k. A
/// box's square cross-section has Z_4 (its faces), a 32-sided ring Z_32 (its segments); every
/// answer differs from another by a symmetry of the normals' spread, a turn by 2 pi / k. All k
/// of them for k up to kMaxTurns (the first is the one rounding of the solver's a picks), the
/// first alone above. None below k = 64 (a sphere, a cylinder of many segments): a is kept.
constexpr int kMaxTurns = 8;
std::vector<Vec3> alignedInPlane(const std::vector<WeightedNormal>& normals, const Vec3& a, const Vec3& b) {
  constexpr int kMaxHarmonic = 64;
  std::vector<std::complex<double>> z(kMaxHarmonic + 1, 0.0);
  for (const WeightedNormal& w : normals) {
    const std::complex<double> u(w.normal.dot(a), w.normal.dot(b));
    const double r = std::abs(u);
    if (r < 1e-12) continue;
    const std::complex<double> step = u / r;
    std::complex<double> power = w.area * r * r;
    for (int k = 0; k <= kMaxHarmonic; ++k, power *= step) z[k] += power;
  }
  for (int k = 1; k <= kMaxHarmonic; ++k)
    if (std::abs(z[k]) > 1e-6 * std::abs(z[0])) {
      std::vector<Vec3> out;
      const double theta = std::arg(z[k]) / k, turn = 2.0 * std::acos(-1.0) / k;
      for (int j = 0; j < (k <= kMaxTurns ? k : 1); ++j)
        out.push_back((std::cos(theta + j * turn) * a + std::sin(theta + j * turn) * b).normalized());
      return out;
    }
  return {a};
}

/// Axes for second moments with (nearly) equal eigenvalues, where the eigenvectors are any basis
/// of their plane or space: the axis among the faces' normals (all three equal) or within the
/// plane (two equal) that most of the surface faces. Boxy models get axes along their faces.
/// Each (e1, e2) the normals allow (the turns of alignedInPlane); {(e1, e2)} as given otherwise.
std::vector<std::pair<Vec3, Vec3>> alignDegenerateAxes(const std::vector<TriMesh>& pieces,
                                                       const std::vector<std::vector<Vec3>>& points,
                                                       const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& eig,
                                                       const Vec3& e1, const Vec3& e2) {
  const Vec3 values = eig.eigenvalues();  // ascending
  // Eigenvectors of eigenvalues a relative gap g apart turn by about (rounding / g) when the
  // input is moved: with g = 2e-6 (knot's largest two) enough to move a few coordinates across a
  // step of the canonical grid, and the parts then change. Below 1e-3 the normals decide.
  const double tolerance = 1e-3 * std::abs(values[2]);
  const bool topTwo = values[2] - values[1] <= tolerance, bottomTwo = values[1] - values[0] <= tolerance;
  if (!topTwo && !bottomTwo) return {{e1, e2}};
  std::vector<WeightedNormal> normals;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (const Face& f : pieces[i].faces) {
      const std::vector<Vec3>& p = points[i];
      const Vec3 n = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
      if (n.norm() > 0.0) normals.push_back({n.normalized(), 0.5 * n.norm()});
    }
  if (normals.empty()) return {{e1, e2}};
  std::vector<std::pair<Vec3, Vec3>> out;
  if (topTwo && bottomTwo) {
    // A sphere-like spread: the first axis is the face normal with the largest alignment (a
    // quadratic search, so only for meshes small enough; larger ones keep the solver's axes).
    if (normals.size() > 4096) return {{e1, e2}};
    double bestValue = -1.0;
    Vec3 first = e1;
    for (const WeightedNormal& w : normals)
      if (const double v = alignment(normals, w.normal); v > bestValue * (1 + 1e-12)) bestValue = v, first = w.normal;
    const Vec3 a = first.unitOrthogonal();
    out.emplace_back(first, alignedInPlane(normals, a, first.cross(a)).front());
  } else if (topTwo) {
    const Vec3 e3 = eig.eigenvectors().col(0).normalized();
    for (const Vec3& d : alignedInPlane(normals, eig.eigenvectors().col(2).normalized(), eig.eigenvectors().col(1).normalized()))
      out.emplace_back(d, e3.cross(d).normalized());
  } else {
    const Vec3 a = eig.eigenvectors().col(1).normalized();
    for (const Vec3& d : alignedInPlane(normals, a, e1.cross(a).normalized())) out.emplace_back(e1, d);
  }
  return out;
}

}  // namespace

Normalization canonicalFrame(const std::vector<TriMesh>& pieces) {
  const Normalization sphere = minimumSphereNormalization(concatenate(pieces));
  Normalization frame = sphere;
  // Moments in the sphere's units (translation and scale removed; rotation is what is sought).
  std::vector<std::vector<Vec3>> points(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (const Vec3& v : pieces[i].vertices) points[i].push_back(sphere.apply(v));
  /// Calls visit(a, b, c, area) for every face, corners relative to `origin`.
  auto forEachFace = [&](const Vec3& origin, const auto& visit) {
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (const Face& f : pieces[i].faces) {
        const Vec3 a = points[i][f[0]] - origin, b = points[i][f[1]] - origin, c = points[i][f[2]] - origin;
        visit(a, b, c, 0.5 * (b - a).cross(c - a).norm());
      }
  };
  double area = 0.0;
  Vec3 centroid = Vec3::Zero();
  forEachFace(Vec3::Zero(), [&](const Vec3& a, const Vec3& b, const Vec3& c, double A) {
    area += A;
    centroid += A * (a + b + c) / 3.0;
  });
  if (!(area > 0.0)) return frame;
  centroid /= area;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  forEachFace(centroid, [&](const Vec3& a, const Vec3& b, const Vec3& c, double A) {
    const Vec3 s = a + b + c;
    second += A / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  });
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(second);
  if (eig.info() != Eigen::Success) return frame;
  const Vec3 e1 = eig.eigenvectors().col(2).normalized(), e2 = eig.eigenvectors().col(1).normalized();  // largest, middle
  // Each candidate's axes, signed by its third moments; where symmetry leaves a choice (turns
  // in a plane of equal second moments, signs of vanishing third moments), the candidate frame
  // in which the mesh reads first (canonicalLess) is taken, the same in every pose. The shape's
  // own triangulation is rarely as symmetric as its geometry, so the choice shows in the parts.
  std::vector<Normalization> candidates;
  for (const auto& [c1, c2] : alignDegenerateAxes(pieces, points, eig, e1, e2)) {
    const Vec3 axes[3] = {c1, c2, c1.cross(c2).normalized()};
    double third[3] = {0.0, 0.0, 0.0};
    forEachFace(centroid, [&](const Vec3& a, const Vec3& b, const Vec3& c, double A) {
      for (int k = 0; k < 3; ++k) third[k] += thirdMoment(A, axes[k].dot(a), axes[k].dot(b), axes[k].dot(c));
    });
    auto oriented = [&](double a, double b) {
      Normalization f = frame;
      f.rotation.row(0) = (a * axes[0]).transpose();
      f.rotation.row(1) = (b * axes[1]).transpose();
      f.rotation.row(2) = (a * b * axes[2]).transpose();
      return f;
    };
    // Flipping e1 or e2 flips e3 = e1 x e2 too, so only two signs are free: the two axes with the
    // larger third moments point where theirs is positive and the third axis follows. A mirror
    // symmetry makes one third moment vanish; it is then the one that follows. Two or three
    // vanishing (two mirror planes, as CAD parts often have) leave signs to choose.
    const double noise = 1e-9 * area;
    int vanishing = 0;
    for (double t : third) vanishing += std::abs(t) <= noise;
    if (vanishing >= 2) {
      for (double a : {1.0, -1.0})
        for (double b : {1.0, -1.0}) {
          const double signs[3] = {a, b, a * b};
          bool allowed = true;
          for (int k = 0; k < 3; ++k) allowed = allowed && (std::abs(third[k]) <= noise || signs[k] * third[k] > 0.0);
          if (allowed) candidates.push_back(oriented(a, b));
        }
      continue;
    }
    int follower = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(third[k]) < std::abs(third[follower])) follower = k;
    auto sign = [](double x) { return x < 0.0 ? -1.0 : 1.0; };
    double s1, s2;  // signs of e1 and e2; e3's is s1 * s2
    if (follower == 2) {
      s1 = sign(third[0]), s2 = sign(third[1]);
    } else if (follower == 1) {
      s1 = sign(third[0]), s2 = sign(third[2]) * s1;
    } else {
      s2 = sign(third[1]), s1 = sign(third[2]) * s2;
    }
    candidates.push_back(oriented(s1, s2));
  }
  if (candidates.size() == 1) return candidates.front();
  const TriMesh whole = concatenate(pieces);
  std::size_t best = 0;
  TriMesh bestMesh = canonicalMesh(whole, candidates[0]).mesh;
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    TriMesh mesh = canonicalMesh(whole, candidates[i]).mesh;
    if (canonicalLess(mesh, bestMesh)) best = i, bestMesh = std::move(mesh);
  }
  return candidates[best];
}

Normalization faceAlignedFrame(const std::vector<TriMesh>& pieces, const Normalization& frame) {
  // Lines of normals binned at 1e-7: the normals of one plane differ by ulps, so they share a bin
  // in every pose (the sign of a line is that of its larger bin key, so n and -n share one too).
  using Key = std::array<long long, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::hash<long long>()(k[0]) ^ (std::hash<long long>()(k[1]) * 31) ^ (std::hash<long long>()(k[2]) * 961);
    }
  };
  struct Line {
    Vec3 sum = Vec3::Zero();  // area-weighted unit normals
    double area = 0.0;
  };
  std::unordered_map<Key, Line, KeyHash> lines;
  double total = 0.0;
  for (const TriMesh& piece : pieces) {
    std::vector<Vec3> p(piece.vertices.size());
    for (std::size_t v = 0; v < p.size(); ++v) p[v] = frame.apply(piece.vertices[v]);
    for (const Face& f : piece.faces) {
      const Vec3 n = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
      const double twice = n.norm();
      if (!(twice > 0.0)) continue;
      Vec3 u = n / twice;
      Key k{std::llround(u.x() * 1e7), std::llround(u.y() * 1e7), std::llround(u.z() * 1e7)};
      const Key opposite{-k[0], -k[1], -k[2]};
      if (opposite > k) k = opposite, u = -u;
      Line& line = lines[k];
      line.sum += 0.5 * twice * u;
      line.area += 0.5 * twice;
      total += 0.5 * twice;
    }
  }
  // The largest, ties by key: the same choice in every pose.
  auto largest = [&](const auto& allowed) -> const Line* {
    const Line* best = nullptr;
    const Key* bestKey = nullptr;
    for (const auto& [key, line] : lines) {
      if (!allowed(line)) continue;
      if (!best || line.area > best->area || (line.area == best->area && key < *bestKey)) best = &line, bestKey = &key;
    }
    return best;
  };
  const Line* first = largest([](const Line&) { return true; });
  if (!first || !(first->area >= kLeastAlignedArea * total)) return frame;
  const Vec3 r1 = first->sum.normalized();
  const Line* second = largest([&](const Line& l) { return std::abs(l.sum.normalized().dot(r1)) <= 1e-9; });
  Vec3 r2;
  if (second) {
    r2 = second->sum.normalized();
  } else {  // the frame's axis least along r1
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (std::abs(r1[j]) < std::abs(r1[k])) k = j;
    r2 = Vec3::Unit(k);
  }
  r2 = (r2 - r2.dot(r1) * r1).normalized();
  Eigen::Matrix3d turn;
  turn.row(0) = r1.transpose();
  turn.row(1) = r2.transpose();
  turn.row(2) = r1.cross(r2).normalized().transpose();
  Normalization aligned = frame;
  aligned.rotation = turn * frame.rotation;
  return aligned;
}

CanonicalMesh canonicalMesh(const TriMesh& mesh, const Normalization& n) {
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<Vec3> moved(nv);
  for (int v = 0; v < nv; ++v) {
    const Vec3 p = n.apply(mesh.vertices[v]);
    moved[v] = Vec3(roundToGrid(p.x()), roundToGrid(p.y()), roundToGrid(p.z()));
  }
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  // Coincident vertices (closer than the grid) keep their input order: the one case where the
  // input's order can show through.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lexLess(moved[a], moved[b]); });
  std::vector<int> rank(nv);
  CanonicalMesh out;
  out.mesh.vertices.reserve(nv);
  for (int i = 0; i < nv; ++i) {
    rank[order[i]] = i;
    out.mesh.vertices.push_back(moved[order[i]]);
  }
  out.source = order;
  out.mesh.faces.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    Face g{rank[f[0]], rank[f[1]], rank[f[2]]};
    const int first = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
    std::rotate(g.begin(), g.begin() + first, g.end());
    out.mesh.faces.push_back(g);
  }
  std::sort(out.mesh.faces.begin(), out.mesh.faces.end());
  return out;
}

bool canonicalLess(const TriMesh& a, const TriMesh& b) {
  if (a.vertices.size() != b.vertices.size()) return a.vertices.size() < b.vertices.size();
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if (lexLess(a.vertices[i], b.vertices[i])) return true;
    if (lexLess(b.vertices[i], a.vertices[i])) return false;
  }
  return a.faces < b.faces;
}

std::size_t CanonicalInverse::KeyHash::operator()(const Vec3& p) const {
  std::size_t h = 0;
  for (int k = 0; k < 3; ++k) {
    std::uint64_t bits;
    const double x = p[k] == 0.0 ? 0.0 : p[k];  // -0 and +0 are the same point
    std::memcpy(&bits, &x, sizeof bits);
    h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  }
  return h;
}

void CanonicalInverse::add(const CanonicalMesh& canonical, const TriMesh& input) {
  exact_.reserve(exact_.size() + canonical.mesh.vertices.size());  // no rehashing on the way
  for (std::size_t i = 0; i < canonical.mesh.vertices.size(); ++i)
    exact_.emplace(canonical.mesh.vertices[i], input.vertices[canonical.source[i]]);
}

Vec3 CanonicalInverse::operator()(const Vec3& p) const {
  const auto it = exact_.find(p);
  return it != exact_.end() ? it->second : frame_.undo(p);
}

TriMesh CanonicalInverse::operator()(const TriMesh& mesh) const {
  TriMesh out = mesh;
  for (Vec3& p : out.vertices) p = (*this)(p);
  return out;
}

}  // namespace acd
