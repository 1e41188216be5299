// Open surfaces in the concavity measure (Section 4.1, Extension 2): concave hull vertices and
// the three projection rules, on sheets whose answers are known.
#include <acd/algo/concavity.hpp>
#include <acd/algo/open_surface.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/normalize.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>
#include <functional>

using namespace acd;
using acdtest::measure;

namespace {

/// Grid sheet over [0, 1] x [0, 1] in (s, t), mapped by `at`, faces counter-clockwise in (s, t).
TriMesh sheet(int ns, int nt, const std::function<Vec3(double, double)>& at) {
  TriMesh m;
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= ns; ++i) m.vertices.push_back(at(double(i) / ns, double(j) / nt));
  auto id = [&](int i, int j) { return j * (ns + 1) + i; };
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < ns; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

/// One period of z = a sin(x) over x in [0, 2 pi], y in [0, 2]; normals point up (+z side).
TriMesh sineSheet(double amplitude) {
  return sheet(64, 4, [&](double s, double t) {
    const double x = 2 * M_PI * s;
    return Vec3(x, 2 * t, amplitude * std::sin(x));
  });
}

/// The sine sheet with its middle crest vertex lifted: a convex hull vertex away from the opening.
TriMesh sineSheetWithPeak() {
  TriMesh m = sineSheet(1.0);
  m.vertices[2 * 65 + 16].z() += 0.5;  // row t = 1/2, x = pi / 2
  return m;
}

/// Lower half of the unit sphere, normals pointing away from the centre when `outward`.
TriMesh bowl(bool outward) {
  TriMesh m = sheet(48, 12, [](double s, double t) {
    const double phi = 2 * M_PI * s, theta = 0.5 * M_PI * t;  // theta 0: bottom pole, pi/2: rim
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
  });
  // The seam (s = 0 and s = 1) and the pole are the same points: weld them.
  TriMesh w;
  std::vector<int> map(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    map[v] = -1;
    for (std::size_t u = 0; u < w.vertices.size(); ++u)
      if ((w.vertices[u] - m.vertices[v]).norm() < 1e-12) map[v] = static_cast<int>(u);
    if (map[v] < 0) map[v] = static_cast<int>(w.vertices.size()), w.vertices.push_back(m.vertices[v]);
  }
  for (Face f : m.faces) {
    for (int& v : f) v = map[v];
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) continue;
    w.faces.push_back(f);
  }
  // Make the faces point away from the centre (outward) or toward it.
  double away = 0;
  for (int f = 0; f < static_cast<int>(w.faces.size()); ++f) away += faceNormal(w, f).dot(w.vertices[w.faces[f][0]]);
  if ((away > 0) != outward)
    for (Face& f : w.faces) std::swap(f[1], f[2]);
  return w;
}

/// Largest distance from a vertex to the boundary of the surface's own hull: for a point inside a
/// convex polytope, its least distance to a facet plane. The true surface concavity.
double distanceToHullBoundary(const TriMesh& mesh) {
  const TriMesh hull = convexHull(mesh.vertices).mesh;
  double worst = 0;
  for (const Vec3& p : mesh.vertices) {
    double d = std::numeric_limits<double>::infinity();
    for (int f = 0; f < static_cast<int>(hull.faces.size()); ++f) {
      const Vec3 n = faceNormal(hull, f).normalized();
      d = std::min(d, n.dot(hull.vertices[hull.faces[f][0]]) - n.dot(p));
    }
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace

TEST(OpenSurface, OutwardBowlHasNoConcaveHullVertexAndNoConcavity) {
  const TriMesh m = applyNormalization(bowl(true), minimumSphereNormalization(bowl(true)));
  const ConvexHull hull = convexHull(m.vertices);
  const auto concave = concaveHullVertices(m, hull);
  EXPECT_EQ(std::count(concave.begin(), concave.end(), 1), 0);
  for (std::size_t h = 0; h < concave.size(); ++h)
    if (concave[h]) ADD_FAILURE() << m.vertices[hull.source[h]].transpose() << " n " << vertexNormals(m)[hull.source[h]].transpose() << " hn " << vertexNormals(hull.mesh)[h].transpose();
  // Every point of a hemisphere lies on its hull: as a surface it is convex.
  EXPECT_LT(distanceToHullBoundary(m), 1e-9);
  EXPECT_LE(measure(m, 0.01).concavity, 0.01);
}

TEST(OpenSurface, InwardBowlIsTurnedToFaceOut) {
  TriMesh m = bowl(false);
  const ConvexHull hull = convexHull(m.vertices);
  const auto concave = concaveHullVertices(m, hull);
  EXPECT_EQ(std::count(concave.begin(), concave.end(), 1), static_cast<long>(concave.size()));
  EXPECT_TRUE(orientTowardHull(m));
  const auto after = concaveHullVertices(m, convexHull(m.vertices));
  EXPECT_EQ(std::count(after.begin(), after.end(), 1), 0);
  EXPECT_FALSE(orientTowardHull(m));  // already facing out
}

TEST(OpenSurface, SineSheetHasConcaveTroughs) {
  const TriMesh m = sineSheet(1.0);
  const ConvexHull hull = convexHull(m.vertices);
  const auto concave = concaveHullVertices(m, hull);
  int concaveCount = 0, convexCount = 0;
  for (std::size_t h = 0; h < concave.size(); ++h) {
    const Vec3& p = m.vertices[hull.source[h]];
    // Hull vertices on the trough's bottom line face up, into the hull: concave. The crest faces out.
    if (std::abs(p.z() + 1.0) < 1e-9) EXPECT_TRUE(concave[h]) << p.transpose();
    if (std::abs(p.z() - 1.0) < 1e-9) EXPECT_FALSE(concave[h]) << p.transpose();
    (concave[h] ? concaveCount : convexCount)++;
  }
  EXPECT_GT(concaveCount, 0);
  EXPECT_GT(convexCount, 0);
}

TEST(OpenSurface, ProjectionRules) {
  const TriMesh m = applyNormalization(sineSheetWithPeak(), minimumSphereNormalization(sineSheetWithPeak()));
  const SurfaceGraph graph(m);
  const ConvexHull hull = convexHull(m.vertices);
  const auto concave = concaveHullVertices(m, hull);
  const auto boundary = boundaryVertices(graph);
  const OpenSurfaceProjection projection(m, graph, hull);
  ASSERT_TRUE(projection.open());
  EXPECT_EQ(projection.concaveVertices(), std::count(concave.begin(), concave.end(), 1));
  PathFinder finder(graph);
  int both = 0, none = 0, mixed = 0;
  for (const Face& f : hull.mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const int u = f[k], v = f[(k + 1) % 3];
      const std::vector<int> path = projection.project(finder, u, v);
      const int a = hull.source[u], b = hull.source[v];
      if (!concave[u] && !concave[v]) {  // as on a closed surface: a shortest path between the ends
        ++both;
        ASSERT_GE(path.size(), 1u);
        EXPECT_EQ(path.front(), a);
        EXPECT_EQ(path.back(), b);
      } else if (concave[u] && concave[v]) {  // no projection
        ++none;
        EXPECT_TRUE(path.empty());
      } else {  // from the convex end to the opening, in the edge's direction
        const int convexEnd = concave[u] ? b : a;
        if (boundary[convexEnd]) {  // already on the opening: nothing to project
          EXPECT_TRUE(path.empty());
          continue;
        }
        ++mixed;
        ASSERT_GE(path.size(), 2u);
        if (!concave[u]) {
          EXPECT_EQ(path.front(), a);
          EXPECT_TRUE(boundary[path.back()]);
        } else {
          EXPECT_EQ(path.back(), b);
          EXPECT_TRUE(boundary[path.front()]);
        }
      }
      for (std::size_t i = 0; i + 1 < path.size(); ++i)  // paths run along mesh edges
        EXPECT_TRUE(graph.faceLeftOf(path[i], path[i + 1]) >= 0 || graph.faceLeftOf(path[i + 1], path[i]) >= 0);
    }
  EXPECT_GT(both, 0);
  EXPECT_GT(none, 0);
  EXPECT_GT(mixed, 0);
}

TEST(OpenSurface, SineSheetConcavityBoundsTheTrueDistance) {
  for (double amplitude : {0.3, 1.0}) {
    SCOPED_TRACE(amplitude);
    const TriMesh raw = sineSheet(amplitude);
    const TriMesh m = applyNormalization(raw, minimumSphereNormalization(raw));
    const double truth = distanceToHullBoundary(m);
    ASSERT_GT(truth, 0.05);  // the flanks lie inside the hull
    const double epsilon = 0.02;
    const double measured = measure(m, epsilon).concavity;
    // Conservative (a pocket's bridge plane is never nearer than the nearest facet plane)...
    EXPECT_GE(measured, truth - 1e-9);
    // ... and not wildly so: below the sheet's own thickness across its hull.
    const Box3 box = boundingBox(m);
    EXPECT_LE(measured, box.size().z() + 1e-9);
  }
}

TEST(OpenSurface, FlatSheetIsConvex) {
  const TriMesh m = sheet(8, 8, [](double s, double t) { return Vec3(s, t, 0.0); });
  EXPECT_EQ(measure(m, 0.01).concavity, 0.0);
}
