// libFuzzer harness for acd::decompose on small generated meshes. The bytes choose a shape
// (a few dozen faces at most, so one run takes milliseconds), perturb its vertices and faces
// (moves, snaps onto other vertices, flips, deletions, duplicates, wild indices, non-finite
// coordinates) and vary the options the command uses (recommendedOptions()). decompose must
// either refuse with a one-line Status or return closed components within tau (or marked
// unresolved) that keep the input's volume; on a clean closed input, the harness checks the
// promise with its own geometry (winding numbers and point-triangle distances, nothing from the
// library): every hull within tau of the input, every input vertex inside a hull, unless the
// result says otherwise (a solid that passes through itself: the library's own check of the
// input as read, what makes acd decompose exit 8).
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_decompose: broken promise: %s\n", what);
  std::abort();
}

acd::TriMesh baseShape(FuzzedDataProvider& in) {
  using acd::Vec3;
  namespace shapes = acd::shapes;
  switch (in.ConsumeIntegralInRange<int>(0, 6)) {
    case 0: return shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
    case 1: return shapes::lShape();
    case 2: return shapes::uShape();
    case 3: return shapes::icosphere(Vec3(0, 0, 0), 1.0, in.ConsumeIntegralInRange<int>(0, 1));
    case 4: return shapes::torus(2.0, 0.6, in.ConsumeIntegralInRange<int>(3, 8), in.ConsumeIntegralInRange<int>(3, 5));
    case 5: {
      // Up to 6 unit cells in a 3x3x3 grid: L, U, stairs, handles, and cells touching along an
      // edge only (a non-manifold input that must be refused, not decomposed).
      std::vector<std::array<int, 3>> cells;
      const int count = in.ConsumeIntegralInRange<int>(1, 6);
      for (int i = 0; i < count; ++i) {
        const int c = in.ConsumeIntegralInRange<int>(0, 26);
        cells.push_back({c % 3, (c / 3) % 3, c / 9});
      }
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      return shapes::voxels(cells);
    }
    default: {
      const int rings = in.ConsumeIntegralInRange<int>(3, 8);
      return shapes::revolve([](double z) { return 0.6 + 0.4 * std::cos(3.0 * z); }, -1.5, 1.5, rings, 6);
    }
  }
}

double smallOffset(FuzzedDataProvider& in) {
  // Quantised so the fuzzer can hit exact zero and exact coincidences.
  return in.ConsumeIntegralInRange<int>(-64, 64) / 128.0;
}

void perturb(FuzzedDataProvider& in, acd::TriMesh& mesh) {
  const int edits = in.ConsumeIntegralInRange<int>(0, 8);
  for (int e = 0; e < edits && !mesh.vertices.empty() && !mesh.faces.empty(); ++e) {
    const int nv = static_cast<int>(mesh.vertices.size()), nf = static_cast<int>(mesh.faces.size());
    const int v = in.ConsumeIntegralInRange<int>(0, nv - 1);
    const int f = in.ConsumeIntegralInRange<int>(0, nf - 1);
    switch (in.ConsumeIntegralInRange<int>(0, 9)) {
      case 0: case 1: case 2:  // move a vertex
        mesh.vertices[v] += acd::Vec3(smallOffset(in), smallOffset(in), smallOffset(in));
        break;
      case 3:  // snap onto another vertex: degenerate faces, pinched surfaces
        mesh.vertices[v] = mesh.vertices[in.ConsumeIntegralInRange<int>(0, nv - 1)];
        break;
      case 4: std::swap(mesh.faces[f][0], mesh.faces[f][1]); break;      // flip
      case 5: mesh.faces.erase(mesh.faces.begin() + f); break;           // a hole
      case 6: mesh.faces.push_back(mesh.faces[f]); break;                // a duplicate
      case 7:  // an index anywhere, out of range included
        mesh.faces[f][in.ConsumeIntegralInRange<int>(0, 2)] = in.ConsumeIntegralInRange<int>(-2, nv + 1);
        break;
      case 8: {  // a non-finite or far-away coordinate
        const double values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                 1e300, 1e-300, -1e12};
        mesh.vertices[v][in.ConsumeIntegralInRange<int>(0, 2)] = values[in.ConsumeIntegralInRange<int>(0, 4)];
        break;
      }
      default: {  // scale the whole mesh: tiny and huge models
        const double scales[] = {1e-9, 1e-3, 1e3, 1e9};
        const double s = scales[in.ConsumeIntegralInRange<int>(0, 3)];
        for (acd::Vec3& p : mesh.vertices) p *= s;
      }
    }
  }
}

// ---- the harness's own geometry: the oracle shares no code with the library

double pointTriangleDistance(const acd::Vec3& p, const acd::Vec3& a, const acd::Vec3& b, const acd::Vec3& c) {
  // Inside the triangle's prism: the distance to its plane; otherwise to the nearest edge.
  const acd::Vec3 n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  auto segment = [&](const acd::Vec3& u, const acd::Vec3& v) {
    const acd::Vec3 e = v - u;
    const double t = std::clamp(e.dot(p - u) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
    return (u + t * e - p).norm();
  };
  if (area2 > 0) {
    const bool inside = n.dot((b - a).cross(p - a)) >= 0 && n.dot((c - b).cross(p - b)) >= 0 &&
                        n.dot((a - c).cross(p - c)) >= 0;
    if (inside) return std::abs(n.dot(p - a)) / std::sqrt(area2);
  }
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

/// Generalised winding number (solid angles, van Oosterom and Strackee): 1 inside a closed
/// outward surface, 0 outside.
double windingNumber(const acd::TriMesh& m, const acd::Vec3& p) {
  double sum = 0.0;
  for (const acd::Face& f : m.faces) {
    const acd::Vec3 a = m.vertices[f[0]] - p, b = m.vertices[f[1]] - p, c = m.vertices[f[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * M_PI);
}

/// Each facet's plane placed at the support of the hull's vertices along its normal: a thin
/// facet's normal may be off by rounding, and a plane through the facet could then cut the hull.
bool insideConvex(const acd::TriMesh& hull, const acd::Vec3& p, double slack) {
  for (const acd::Face& f : hull.faces) {
    const acd::Vec3 n = (hull.vertices[f[1]] - hull.vertices[f[0]]).cross(hull.vertices[f[2]] - hull.vertices[f[0]]);
    const double len = n.norm();
    if (!(len > 0)) continue;
    double support = -std::numeric_limits<double>::infinity();
    for (const acd::Vec3& v : hull.vertices) support = std::max(support, n.dot(v) / len);
    if (n.dot(p) / len - support > slack) return false;
  }
  return true;
}

/// Edges used once each way: a clean closed input, on which "outside" is well defined.
bool cleanClosed(const acd::TriMesh& m) {
  std::vector<std::pair<int, int>> edges;
  for (const acd::Face& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      if (f[k] < 0 || f[k] >= static_cast<int>(m.vertices.size())) return false;
      edges.emplace_back(f[k], f[(k + 1) % 3]);
    }
  for (const acd::Vec3& v : m.vertices)
    if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) return false;
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
  for (const auto& [a, b] : edges)
    if (a == b || !std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) return false;
  return true;
}

/// One piece: every face reachable from the first across shared edges. Several shells that cross,
/// nest or are inside out have no one agreed solid (a winding number and a parity test disagree
/// where they overlap), so the harness checks the promise on single clean solids only.
bool onePiece(const acd::TriMesh& m) {
  std::vector<int> parent(m.vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const acd::Face& f : m.faces) parent[find(f[0])] = find(f[1]), parent[find(f[1])] = find(f[2]);
  const int root = find(m.faces[0][0]);
  for (const acd::Face& f : m.faces)
    if (find(f[0]) != root) return false;
  return true;
}

/// The promise, measured by the harness: hull points outside the input lie within tau of its
/// surface, and every input vertex lies in some hull (both with a sliver of slack for rounding
/// and for the library's sampled measure).
void checkPromise(const acd::TriMesh& input, const acd::Decomposition& d) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = input.vertices[0][k];
  for (const acd::Vec3& v : input.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  // The library's unit (minimum enclosing sphere radius), checked against the box it must fit.
  const double radius = 1.0 / d.normalization.scale;
  require(radius <= 0.5 * diagonal * (1 + 1e-9) && radius >= 0.5 * diagonal / std::sqrt(3.0) * (1 - 1e-9),
          "the model's unit does not fit its bounding box");
  const double tau = d.options.tau * radius;
  for (const acd::Component& c : d.components) {
    if (c.unresolved) continue;
    const acd::TriMesh& h = c.hull;
    for (const acd::Face& f : h.faces)
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; i + j <= 4; ++j) {
          const acd::Vec3 p = h.vertices[f[0]] + (h.vertices[f[1]] - h.vertices[f[0]]) * (i / 4.0) +
                              (h.vertices[f[2]] - h.vertices[f[0]]) * (j / 4.0);
          if (windingNumber(input, p) > 0.5) continue;
          double best = std::numeric_limits<double>::infinity();
          for (const acd::Face& g : input.faces)
            best = std::min(best, pointTriangleDistance(p, input.vertices[g[0]], input.vertices[g[1]], input.vertices[g[2]]));
          // A solid that passes through itself may end so (its repair moves the surface): the
          // result must then say it, as acd decompose does with exit 8.
          if (best > 1.1 * tau + 1e-9 * diagonal) {
            require(!acd::hullsOffInput(input, d, true).kept,
                    "a hull stands off the input by more than tau (harness's measure), not reported");
            return;
          }
        }
  }
  for (const acd::Vec3& v : input.vertices) {
    bool covered = false;
    for (const acd::Component& c : d.components) covered = covered || insideConvex(c.hull, v, 1e-7 * diagonal);
    if (!covered) {
      require(acd::inputOutsideHulls(input, d).max > 0.0, "an input vertex outside every hull (harness's measure), not reported");
      return;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  acd::TriMesh mesh = baseShape(in);
  perturb(in, mesh);

  acd::DecomposeOptions options = acd::recommendedOptions();  // what users get
  const double taus[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.5};
  options.tau = taus[in.ConsumeIntegralInRange<int>(0, 5)];
  options.featureGrouping = in.ConsumeBool();
  options.merge = in.ConsumeBool();
  if (in.ConsumeBool()) options.mergeScope = acd::MergeScope::Component;  // the library's own default
  options.uniteShells = in.ConsumeBool();
  options.fillHoles = in.ConsumeBool();
  // The wrap's size grows as 1/tau^2: below tau 0.1 a wrapped 20-face sheet has 5,000-70,000 faces
  // and takes 10-230 s in the Release build, minutes under the sanitizers. Those inputs are
  // refused instead (the repairs before the wrap are fuzzed at every tau).
  options.wrap = options.tau >= 0.1;
  options.threads = 1;
  options.maxComponents = 24;  // bounds the work per input; pieces beyond it come back unresolved

  // Triage: ACD_FUZZ_DUMP=PREFIX writes the generated mesh to PREFIX.off and prints the options,
  // so that a finding can be replayed with `acd decompose` outside the fuzzer.
  if (const char* dump = std::getenv("ACD_FUZZ_DUMP")) {
    const acd::Status written = acd::writeMesh(std::string(dump) + ".off", mesh);
    std::fprintf(stderr, "fuzz_decompose: %s.off (%s): -t %g%s%s%s%s%s%s --threads 1\n", dump,
                 written.ok() ? "written" : written.message.c_str(), options.tau,
                 options.featureGrouping ? "" : " --no-grouping", options.merge ? "" : " --no-merge",
                 options.mergeScope == acd::MergeScope::Component ? " --merge-scope component" : "",
                 options.uniteShells ? " --union" : "", options.fillHoles ? "" : " --no-fill-holes",
                 options.wrap ? "" : " --no-wrap");
  }

  const acd::Decomposition d = acd::decompose(mesh, options);
  if (!d.status.ok()) {
    require(!d.status.message.empty(), "a refusal without a message");
    require(d.status.message.find('\n') == std::string::npos, "a refusal message of several lines");
    require(d.components.empty(), "components left after a refusal");
    return 0;
  }
  require(!d.components.empty(), "success with no components");
  // On a clean single solid the promise holds for every resolved component. On a soup (crossing,
  // nested, inside-out or broken shells) or a surface that passes through itself, a hull may end
  // beyond tau, through the wrap or the per-shell fallback: the library reports it in hullExcess
  // and `acd decompose` exits 8 with the reason, so the harness asks only that it is reported.
  // (Whether the surface crosses itself is the library's exact test; the promise's measure below
  // stays the harness's own.)
  const bool cleanSolid =
      !mesh.faces.empty() && cleanClosed(mesh) && onePiece(mesh) && acd::countSelfIntersections(mesh, 1) == 0;
  double volume = 0.0;
  for (const acd::Component& c : d.components) {
    require(!c.mesh.faces.empty(), "an empty component");
    require(acd::isClosedOriented(c.mesh), "a component that is not closed and oriented");
    require(std::isfinite(c.concavity) && std::isfinite(c.volume), "a non-finite component measure");
    // A merged component's own concavity is promised only with the merge held to each component.
    require(c.unresolved || d.options.mergeScope == acd::MergeScope::Model || c.concavity <= d.options.tau * (1 + 1e-9),
            "a resolved component above tau");
    require(std::isfinite(c.hullExcess) && c.hullExcess >= 0, "a hull excess that is not a distance");
    require(c.unresolved || !cleanSolid || c.hullExcess <= d.options.tau * (1 + 1e-9),
            "a resolved component's hull beyond tau on a clean solid");
    volume += c.volume;
  }
  // Cuts neither add nor lose volume (normalised units, so the bound is scale-free).
  require(std::abs(volume - d.stats.inputVolume) <= 1e-6 * std::max(1.0, d.stats.inputVolume),
          "the components' volume differs from the input's");
  if (cleanSolid) checkPromise(mesh, d);
  return 0;
}
