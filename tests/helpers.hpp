// Helpers shared by the tests: an exact-enough point-in-solid test (signed crossings of a +z
// ray, watertight over shared edges), point-to-surface distance through a small BVH, uniform
// surface sampling, temporary folders and running the built commands; the corpus, moved and
// normalised copies of a mesh, its concavity and its decomposition as most tests want them.
#pragma once

#include <acd/algo/closest_point.hpp>
#include <acd/algo/concavity.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/decompose.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/normalize.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace acdtest {

using acd::Face;
using acd::TriMesh;
using acd::Vec3;

#ifdef ACD_DATA_DIR
/// A model of the corpus: data/meshes/NAME.off.
inline std::string corpus(const std::string& name) { return std::string(ACD_DATA_DIR) + "/meshes/" + name + ".off"; }
#endif

/// The mesh rotated by r, then moved by t.
inline TriMesh moved(const TriMesh& m, const Eigen::Matrix3d& r, const Vec3& t) {
  TriMesh out = m;
  for (Vec3& p : out.vertices) p = r * p + t;
  return out;
}

/// A rotation drawn uniformly: a quaternion of four normal draws, normalised.
inline Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const double w = g(rng), x = g(rng), y = g(rng), z = g(rng);  // drawn in this order
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

/// The mesh in normalised units (minimum enclosing sphere of radius 1).
inline TriMesh normalised(const TriMesh& m) { return acd::applyNormalization(m, acd::minimumSphereNormalization(m)); }

/// The concavity measure of a mesh already in normalised units.
inline acd::ConcavityMap measure(const TriMesh& mesh, double epsilon) {
  acd::SurfaceGraph graph(mesh);
  acd::ConcavityOptions o;
  o.epsilon = epsilon;
  return acd::measureConcavity(mesh, graph, o);
}

/// The solid decomposition at tau on two threads, expected to succeed.
inline acd::Decomposition decomposed(const TriMesh& mesh, double tau) {
  acd::DecomposeOptions o;
  o.tau = tau;
  o.threads = 2;
  acd::Decomposition d = acd::decompose(mesh, o);
  EXPECT_TRUE(d.status.ok()) << d.status.message;
  return d;
}

/// Every triangle split into four at its edges' middles: the same surface, four times the faces
/// (how the dense inputs of the benchmarks are made).
inline TriMesh midpointSubdivided(const TriMesh& m) {
  TriMesh out;
  out.vertices = m.vertices;
  std::map<std::pair<int, int>, int> middle;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, fresh] = middle.emplace(key, static_cast<int>(out.vertices.size()));
    if (fresh) out.vertices.push_back(0.5 * (m.vertices[a] + m.vertices[b]));
    return it->second;
  };
  for (const Face& f : m.faces) {
    const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    out.faces.push_back({f[0], ab, ca});
    out.faces.push_back({ab, f[1], bc});
    out.faces.push_back({ca, bc, f[2]});
    out.faces.push_back({ab, bc, ca});
  }
  return out;
}

using acd::closestPointOnTriangle;

/// Bounding-volume hierarchy over the faces of one closed, oriented mesh.
class MeshIndex {
 public:
  explicit MeshIndex(const TriMesh& mesh) : mesh_(mesh) {
    const int n = static_cast<int>(mesh.faces.size());
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    centroid_.resize(n);
    for (int f = 0; f < n; ++f) {
      const Face& t = mesh.faces[f];
      centroid_[f] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    }
    nodes_.reserve(2 * std::max(n, 1));
    if (n > 0) build(0, n);
  }

  const TriMesh& mesh() const { return mesh_; }
  Vec3 lo() const { return nodes_.empty() ? Vec3::Zero() : nodes_[0].lo; }
  Vec3 hi() const { return nodes_.empty() ? Vec3::Zero() : nodes_[0].hi; }

  /// Winding number of the surface around p, from signed crossings of the ray p + t*z (t > 0).
  /// Each undirected edge's side test is evaluated once in a canonical direction, so a ray
  /// through a shared edge is counted by exactly one of its faces (watertight).
  int winding(const Vec3& p) const {
    if (nodes_.empty()) return 0;
    int sum = 0;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (p.x() < node.lo.x() || p.x() > node.hi.x() || p.y() < node.lo.y() || p.y() > node.hi.y() ||
          node.hi.z() < p.z())
        continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) sum += crossing(order_[i], p);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
    return sum;
  }

  bool inside(const Vec3& p) const { return winding(p) != 0; }

  /// Distance from p to the surface.
  double distance(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    std::vector<std::pair<double, int>> stack{{boxDistance2(nodes_[0], p), 0}};
    while (!stack.empty()) {
      const auto [d2, id] = stack.back();
      stack.pop_back();
      if (d2 >= best * best) continue;
      const Node& node = nodes_[id];
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) {
          const Face& t = mesh_.faces[order_[i]];
          const Vec3 q = closestPointOnTriangle(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
          best = std::min(best, (q - p).norm());
        }
      } else {
        const double dl = boxDistance2(nodes_[node.left], p), dr = boxDistance2(nodes_[node.right], p);
        // Nearer child last so that it is popped first.
        if (dl < dr) {
          stack.emplace_back(dr, node.right);
          stack.emplace_back(dl, node.left);
        } else {
          stack.emplace_back(dl, node.left);
          stack.emplace_back(dr, node.right);
        }
      }
    }
    return best;
  }

 private:
  struct Node {
    Vec3 lo, hi;
    int left = -1, right = -1;
    int first = 0, count = 0;
  };

  static double boxDistance2(const Node& n, const Vec3& p) {
    const Vec3 d = (n.lo - p).cwiseMax(p - n.hi).cwiseMax(Vec3::Zero());
    return d.squaredNorm();
  }

  int build(int first, int last) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    Vec3 clo = lo, chi = hi;
    for (int i = first; i < last; ++i) {
      for (int v : mesh_.faces[order_[i]]) {
        lo = lo.cwiseMin(mesh_.vertices[v]);
        hi = hi.cwiseMax(mesh_.vertices[v]);
      }
      clo = clo.cwiseMin(centroid_[order_[i]]);
      chi = chi.cwiseMax(centroid_[order_[i]]);
    }
    nodes_[id].lo = lo;
    nodes_[id].hi = hi;
    if (last - first <= 8) {
      nodes_[id].first = first;
      nodes_[id].count = last - first;
      return id;
    }
    int axis = 0;
    (chi - clo).maxCoeff(&axis);
    const int mid = (first + last) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + last,
                     [&](int a, int b) { return centroid_[a][axis] < centroid_[b][axis]; });
    const int left = build(first, mid);
    const int right = build(mid, last);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
  }

  /// Side of p against directed edge a->b in the xy-plane, evaluated in the canonical
  /// direction (smaller index first) so both faces of an edge agree; zero counts as positive.
  int edgeSide(int a, int b, const Vec3& p) const {
    const bool flip = a > b;
    const Vec3& u = mesh_.vertices[flip ? b : a];
    const Vec3& v = mesh_.vertices[flip ? a : b];
    const double o = (v.x() - u.x()) * (p.y() - u.y()) - (v.y() - u.y()) * (p.x() - u.x());
    const int s = o >= 0 ? 1 : -1;
    return flip ? -s : s;
  }

  int crossing(int f, const Vec3& p) const {
    const Face& t = mesh_.faces[f];
    const int s0 = edgeSide(t[0], t[1], p), s1 = edgeSide(t[1], t[2], p), s2 = edgeSide(t[2], t[0], p);
    if (s0 != s1 || s1 != s2) return 0;
    const Vec3& a = mesh_.vertices[t[0]];
    const Vec3 n = (mesh_.vertices[t[1]] - a).cross(mesh_.vertices[t[2]] - a);
    if (n.z() == 0.0) return 0;
    const double z = a.z() - (n.x() * (p.x() - a.x()) + n.y() * (p.y() - a.y())) / n.z();
    return z > p.z() ? s0 : 0;
  }

  const TriMesh& mesh_;
  std::vector<int> order_;
  std::vector<Vec3> centroid_;
  std::vector<Node> nodes_;
};

/// A point from three draws taken in x, y, z order. In Vec3(u(rng), u(rng), u(rng)) the order is
/// the compiler's (GCC evaluates a call's arguments right to left, clang left to right), and the
/// GCC and clang builds would test different points.
template <class Draw>
Vec3 drawPoint(Draw&& draw) {
  const double x = draw();
  const double y = draw();
  const double z = draw();
  return Vec3(x, y, z);
}

/// The generalised winding number of a mesh around q, the tests' own: its triangles' signed solid
/// angles (Van Oosterom & Strackee) summed over 4 pi; 1 inside a closed outward mesh, 0 outside.
inline double windingSummed(const TriMesh& m, const Vec3& q) {
  double sum = 0.0;
  for (const acd::Face& f : m.faces) {
    const Vec3 a = m.vertices[f[0]] - q, b = m.vertices[f[1]] - q, c = m.vertices[f[2]] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return sum / (4.0 * M_PI);
}

/// n points uniform in the cube [-1, 1]^3 (or, with `ball`, in the unit ball), from `seed`.
inline std::vector<Vec3> randomPoints(int n, std::uint64_t seed, bool ball = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) {
    const Vec3 q = drawPoint([&] { return uni(rng); });
    if (!ball || q.norm() <= 1.0) p.push_back(q);
  }
  return p;
}

/// Uniform random points on the surface (area-weighted).
inline std::vector<Vec3> sampleSurface(const TriMesh& mesh, int count, std::mt19937_64& rng) {
  std::vector<double> cumulative;
  double total = 0;
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    total += 0.5 * acd::faceNormal(mesh, f).norm();
    cumulative.push_back(total);
  }
  std::vector<Vec3> out;
  if (total <= 0) return out;
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double r = uni(rng) * total;
    const int f = static_cast<int>(std::min<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(), cumulative.size() - 1));
    double s = uni(rng), t = uni(rng);
    if (s + t > 1) s = 1 - s, t = 1 - t;
    const Face& tri = mesh.faces[f];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    out.push_back(a + s * (b - a) + t * (c - a));
  }
  return out;
}

/// A fresh directory under the temp directory, unique per test and process, removed on destruction.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    path_ = std::filesystem::temp_directory_path() / ("acd_" + tag + "_" + std::to_string(::getpid()));
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// Exit code and captured output of one run of a built command.
struct ToolRun {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Single-quoted for the shell.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs `binary ARGS` with stdin closed and stdout/stderr captured through files in `dir`.
inline ToolRun runTool(const std::string& binary, const std::string& args, const TempDir& dir) {
  const std::string out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = quote(binary) + " " + args + " >" + quote(out) + " 2>" + quote(err) + " </dev/null";
  const int status = std::system(cmd.c_str());
  ToolRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace acdtest
