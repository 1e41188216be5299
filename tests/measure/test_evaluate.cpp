#include <acd/decompose.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <string>

using namespace acd;

namespace {

EvaluateOptions fastOptions() {
  EvaluateOptions o;
  o.volumeSamples = 200'000;
  o.surfaceSamples = 50'000;
  o.seed = 7;
  return o;
}

TriMesh scaledAbout(const TriMesh& m, const Vec3& c, double s) {
  TriMesh out = m;
  for (Vec3& p : out.vertices) p = c + s * (p - c);
  return out;
}

TriMesh reversed(TriMesh m) {
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// Mean and variance of the distance from a uniform point on the surface of box [lo2, hi2] to the
/// solid box [lo, hi] (midpoint rule).
void boxSurfaceDistanceMoments(const Vec3& lo, const Vec3& hi, const Vec3& lo2, const Vec3& hi2, double& mean,
                               double& var) {
  const int n = 300;
  double area = 0, s1 = 0, s2 = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      const double du = (hi2[u] - lo2[u]) / n, dw = (hi2[w] - lo2[w]) / n;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          Vec3 p;
          p[axis] = side ? hi2[axis] : lo2[axis];
          p[u] = lo2[u] + (i + 0.5) * du;
          p[w] = lo2[w] + (j + 0.5) * dw;
          const double d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0).norm();
          area += du * dw;
          s1 += d * du * dw;
          s2 += d * d * du * dw;
        }
    }
  mean = s1 / area;
  var = s2 / area - mean * mean;
}

}  // namespace

TEST(Evaluate, BoxWithItsOwnHullIsExact) {
  const TriMesh model = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const Evaluation e = evaluate(model, {model}, fastOptions());
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_EQ(e.hulls, 1);
  EXPECT_EQ(e.skippedHulls, 0);
  const double r = std::sqrt(14.0) / 2;  // half-diagonal = enclosing radius
  EXPECT_NEAR(e.modelVolume, 6.0 / (r * r * r), 1e-12);
  EXPECT_NEAR(e.boxVolume, e.modelVolume, 1e-12);
  EXPECT_EQ(e.volumeSamples, 200'000);
  EXPECT_LE(e.misclassifiedShare, 1e-5);
  EXPECT_GE(e.iou, 1.0 - 1e-5);
  EXPECT_NEAR(e.unionToModelRatio, 1.0, 1e-5);
  EXPECT_LT(e.hullOutsideMax, 1e-9);
  EXPECT_LT(e.modelToHullsMax, 1e-9);
  EXPECT_GE(e.seconds, 0.0);
}

TEST(Evaluate, BoxWithEnlargedHull) {
  const Vec3 lo(0, 0, 0), hi(1, 2, 3), c = 0.5 * (lo + hi);
  const TriMesh model = shapes::box(lo, hi);
  const TriMesh hull = scaledAbout(model, c, 1.1);
  const EvaluateOptions o = fastOptions();
  const Evaluation e = evaluate(model, {hull}, o);
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  const double tol = std::max(4 * e.unionVolumeStdErr / e.modelVolume, 1e-9);
  EXPECT_NEAR(e.unionToModelRatio, 1.331, tol);
  EXPECT_NEAR(e.iou, 1 / 1.331, 4 * e.iouStdErr + 1e-9);
  EXPECT_NEAR(e.misclassifiedShare, 1 - 1 / 1.331, 0.01);
  // Farthest hull points are its corners: 0.1 half-diagonals out, i.e. 0.1 in normalised units.
  EXPECT_LE(e.hullOutsideMax, 0.1 + 1e-9);
  EXPECT_GE(e.hullOutsideMax, 0.097);
  const Normalization n = minimumSphereNormalization(model);
  double mean, var;
  boxSurfaceDistanceMoments(lo, hi, c + 1.1 * (lo - c), c + 1.1 * (hi - c), mean, var);
  const double se = std::sqrt(var / o.surfaceSamples) * n.scale;
  EXPECT_NEAR(e.hullOutsideMean, mean * n.scale, 4 * se + 1e-5);
  EXPECT_EQ(e.modelToHullsMax, 0.0);
  EXPECT_EQ(e.modelToHullsMean, 0.0);
}

TEST(Evaluate, ShrunkHullLeavesModelUncovered) {
  const Vec3 lo(0, 0, 0), hi(1, 2, 3), c = 0.5 * (lo + hi);
  const TriMesh model = shapes::box(lo, hi);
  const Evaluation e = evaluate(model, {scaledAbout(model, c, 0.9)}, fastOptions());
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_NEAR(e.unionToModelRatio, 0.729, 4 * e.unionVolumeStdErr / e.modelVolume);
  EXPECT_NEAR(e.iou, 0.729, 4 * e.iouStdErr);
  EXPECT_LT(e.hullOutsideMax, 1e-9);
  // Model corners are 0.1 half-diagonals from the shrunk hull.
  EXPECT_LE(e.modelToHullsMax, 0.1 + 1e-9);
  EXPECT_GE(e.modelToHullsMax, 0.097);
}

// The promise's coverage check: a box against a hull cut short of its top, in the box's own units.
TEST(SurfaceOutsideHulls, KnownDistanceAndTheSamePointOnAnyThreadCount) {
  const TriMesh model = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const TriMesh shorter = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 2.5));
  const Coverage one = surfaceOutsideHulls(model, {shorter}, 20000, 1, 1);
  EXPECT_NEAR(one.max, 0.5, 1e-9);  // the top face stands 0.5 above the hull
  EXPECT_NEAR(one.worst.z(), 3.0, 1e-9);
  // 8 vertices and 50k samples in blocks across two workers: the same point as one pass.
  const Coverage many = surfaceOutsideHulls(model, {shorter}, 50000, 7, 2);
  const Coverage single = surfaceOutsideHulls(model, {shorter}, 50000, 7, 1);
  EXPECT_EQ(many.max, single.max);
  EXPECT_EQ(many.worst, single.worst);
  // Inside: nothing outside, and no point named.
  const Coverage covered = surfaceOutsideHulls(shorter, {model}, 20000, 1, 2);
  EXPECT_EQ(covered.max, 0.0);
  EXPECT_EQ(covered.worst, Vec3::Zero());
  // A box shrunk about its centre leaves its corners outside by a tenth of the half-diagonal.
  const TriMesh shrunk = shapes::box(Vec3(0.05, 0.1, 0.15), Vec3(0.95, 1.9, 2.85));
  EXPECT_NEAR(surfaceOutsideHulls(model, {shrunk}, 0, 1, 2).max, 0.1 * std::sqrt(0.25 + 1 + 2.25), 1e-9);
}

TEST(Evaluate, LShapeWithItsConvexPieces) {
  const TriMesh model = shapes::lShape();
  const std::vector<std::vector<TriMesh>> decompositions = {
      {shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1)), shapes::box(Vec3(0, 1, 0), Vec3(1, 2, 1))},
      {shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1)),
       shapes::box(Vec3(0, 1, 0), Vec3(1, 2, 1))}};
  for (const auto& hulls : decompositions) {
    const Evaluation e = evaluate(model, hulls, fastOptions());
    ASSERT_TRUE(e.status.ok()) << e.status.message;
    EXPECT_EQ(e.hulls, static_cast<int>(hulls.size()));
    EXPECT_LE(e.misclassifiedShare, 1e-5);
    EXPECT_GE(e.iou, 1.0 - 1e-5);
    EXPECT_NEAR(e.unionToModelRatio, 1.0, 4 * e.unionVolumeStdErr / e.modelVolume + 1e-5);
    EXPECT_LT(e.hullOutsideMax, 1e-9);
    EXPECT_LT(e.modelToHullsMax, 1e-9);
  }
}

TEST(Evaluate, LShapeWithOneHullOfBadInput) {
  // The hull is given as the (non-convex, inside-out) L itself: it is replaced by its convex hull.
  const TriMesh model = shapes::lShape();
  const Evaluation e = evaluate(model, {reversed(model)}, fastOptions());
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_NEAR(e.unionToModelRatio, 3.5 / 3.0, 4 * e.unionVolumeStdErr / e.modelVolume);
  EXPECT_NEAR(e.iou, 3.0 / 3.5, 4 * e.iouStdErr);
  // Farthest hull points: the cut-off edge from (2,1) to (1,2), half a unit from the L.
  const double scale = minimumSphereNormalization(model).scale;
  EXPECT_LE(e.hullOutsideMax, 0.5 * scale + 1e-9);
  EXPECT_GE(e.hullOutsideMax, 0.49 * scale);
  EXPECT_EQ(e.modelToHullsMax, 0.0);
}

TEST(Evaluate, MonteCarloModelVolumeOfCurvedSolids) {
  // Exercises the point-in-model test on a non-convex solid of genus 1 and on a convex one.
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const TriMesh ball = shapes::icosphere(Vec3(0.3, -0.2, 0.1), 1.5, 3);
  for (const TriMesh* model : {&torus, &ball}) {
    const Evaluation e = evaluate(*model, {*model}, fastOptions());
    ASSERT_TRUE(e.status.ok()) << e.status.message;
    const double p = static_cast<double>(e.samplesInModel) / e.volumeSamples;
    const double se = e.boxVolume * std::sqrt(p * (1 - p) / e.volumeSamples);
    EXPECT_NEAR(e.boxVolume * p, e.modelVolume, 4 * se);
    EXPECT_LT(e.modelToHullsMax, 1e-9);  // the hull covers the model
  }
}

TEST(Evaluate, IndependentOfThreadCount) {
  const TriMesh model = shapes::lShape();
  EvaluateOptions o = fastOptions();
  o.threads = 1;
  const Evaluation a = evaluate(model, {model}, o);
  o.threads = 2;
  const Evaluation b = evaluate(model, {model}, o);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  EXPECT_EQ(a.samplesInModel, b.samplesInModel);
  EXPECT_EQ(a.samplesInUnion, b.samplesInUnion);
  EXPECT_EQ(a.samplesInBoth, b.samplesInBoth);
  EXPECT_EQ(a.unionVolume, b.unionVolume);
  EXPECT_EQ(a.iou, b.iou);
  EXPECT_EQ(a.hullOutsideMean, b.hullOutsideMean);
  EXPECT_EQ(a.hullOutsideMax, b.hullOutsideMax);
  EXPECT_EQ(a.modelToHullsMean, b.modelToHullsMean);
  o.seed = 8;
  const Evaluation c = evaluate(model, {model}, o);
  EXPECT_NE(a.samplesInUnion, c.samplesInUnion);

  // Nor on how a hull is given: vertex order and face orientation do not matter.
  TriMesh shuffled = reversed(model);
  std::vector<int> perm(shuffled.vertices.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>((i * 5 + 3) % perm.size());
  ASSERT_EQ(std::set<int>(perm.begin(), perm.end()).size(), perm.size());
  TriMesh permuted = shuffled;
  for (std::size_t i = 0; i < perm.size(); ++i) permuted.vertices[perm[i]] = shuffled.vertices[i];
  for (Face& f : permuted.faces)
    for (int& v : f) v = perm[v];
  o.seed = 7;
  const Evaluation d = evaluate(model, {permuted}, o);
  ASSERT_TRUE(d.status.ok());
  EXPECT_EQ(a.samplesInUnion, d.samplesInUnion);
  EXPECT_EQ(a.hullOutsideMean, d.hullOutsideMean);
  EXPECT_EQ(a.modelToHullsMean, d.modelToHullsMean);
}

TEST(Evaluate, MonteCarloModelVolumeOfCorpusMesh) {
  const std::string path = std::string(ACD_DATA_DIR) + "/meshes/armadillo.off";
  if (!std::ifstream(path)) GTEST_SKIP() << path << " not present";
  const ReadResult r = readMesh(path);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EvaluateOptions o = fastOptions();
  o.surfaceSamples = 2000;
  const Evaluation e = evaluate(r.mesh, {r.mesh}, o);
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  const double p = static_cast<double>(e.samplesInModel) / e.volumeSamples;
  EXPECT_NEAR(e.boxVolume * p, e.modelVolume, 4 * e.boxVolume * std::sqrt(p * (1 - p) / e.volumeSamples));
  EXPECT_EQ(e.samplesInBoth, e.samplesInModel);  // the model lies inside its convex hull
  EXPECT_EQ(e.modelToHullsMax, 0.0);
}

TEST(Evaluate, DegenerateHullsAreSkipped) {
  const TriMesh model = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  TriMesh flat = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 0));  // all corners coplanar
  TriMesh few;
  few.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  few.faces = {{0, 1, 2}};
  EvaluateOptions o = fastOptions();
  o.surfaceSamples = 1000;
  const Evaluation e = evaluate(model, {flat, model, few}, o);
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_EQ(e.hulls, 1);
  EXPECT_EQ(e.skippedHulls, 2);
  EXPECT_NE(e.status.message.find("skipped 2"), std::string::npos);
  EXPECT_GE(e.iou, 1.0 - 1e-5);

  const Evaluation none = evaluate(model, {flat, few}, o);
  EXPECT_EQ(none.status.code, StatusCode::InvalidParameter);
}

TEST(Evaluate, BadInput) {
  const TriMesh model = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EvaluateOptions o = fastOptions();
  o.volumeSamples = 1000;
  o.surfaceSamples = 1000;

  EXPECT_EQ(evaluate(TriMesh{}, {model}, o).status.code, StatusCode::EmptyMesh);

  TriMesh open = model;
  open.faces.pop_back();
  const Evaluation eo = evaluate(open, {model}, o);
  EXPECT_EQ(eo.status.code, StatusCode::OpenMesh);
  EXPECT_NE(eo.status.message.find("model"), std::string::npos);

  const Evaluation en = evaluate(model, {}, o);
  EXPECT_EQ(en.status.code, StatusCode::InvalidParameter);
  EXPECT_NE(en.status.message.find("no hulls"), std::string::npos);

  TriMesh nan = model;
  nan.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(evaluate(nan, {model}, o).status.code, StatusCode::NonFiniteVertex);
  TriMesh inf = model;
  inf.vertices[5].x() = std::numeric_limits<double>::infinity();
  const Evaluation eh = evaluate(model, {model, inf}, o);
  EXPECT_EQ(eh.status.code, StatusCode::NonFiniteVertex);
  EXPECT_NE(eh.status.message.find("hull 1"), std::string::npos);

  TriMesh bad = model;
  bad.faces[0][1] = 99;
  EXPECT_EQ(evaluate(bad, {model}, o).status.code, StatusCode::IndexOutOfRange);

  o.volumeSamples = 0;
  EXPECT_EQ(evaluate(model, {model}, o).status.code, StatusCode::InvalidParameter);
}

// hullsOffInput: a sealed enclosure made of two shells, a cup and its lid. The cavity between
// them is outside the input (inside neither shell), though a repair that welds the shells would
// make it an inner shell and fill it: a hull across it stands off the input by the distance to
// the cavity's walls, known in closed form.
TEST(HullsOffInput, HullAcrossTheSealedCavityOfACupAndItsLid) {
  std::vector<std::array<int, 3>> cells;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 2; ++z)
        if (!(x == 1 && y == 1 && z == 1)) cells.push_back({x, y, z});
  const TriMesh cup = shapes::voxels(cells);
  const TriMesh lid = shapes::box(Vec3(0, 0, 2), Vec3(3, 3, 2.25));
  const TriMesh input = concatenate({cup, lid});
  Decomposition d;
  d.options.tau = 0.05;
  d.normalization = minimumSphereNormalization(input);
  Component low, whole;
  low.hull = shapes::box(Vec3(0, 0, 0), Vec3(3, 3, 1.5));    // its top crosses the cavity's middle
  whole.hull = shapes::box(Vec3(0, 0, 0), Vec3(3, 3, 2.25)); // on the input's outer surface
  d.components = {whole, low};
  const HullsOffInput off = hullsOffInput(input, d);
  const double s = d.normalization.scale;
  ASSERT_EQ(off.excess.size(), 2u);
  EXPECT_LT(off.excess[0], 1e-9);
  // The cavity is [1,2]^2 x [1,2]: its centre is 0.5 from every wall. Above tau, the value is
  // within 5% below the excess.
  EXPECT_LE(off.excess[1], 0.5 * s + 1e-9);
  EXPECT_GE(off.excess[1], 0.95 * 0.5 * s);
  EXPECT_EQ(off.component, 1);
  EXPECT_NEAR(off.worst.z(), 1.5, 1e-9);
  EXPECT_EQ(off.openShells, 0);
}

// A hull inside a slab: nothing off the input while the slab is closed, nor with one side of the
// slab missing (it still winds around the hull); against the slab's top alone (a sheet, which
// bounds nothing) the hull's bottom stands 0.2 below it.
TEST(HullsOffInput, OpenShellsBoundWhereTheyWind) {
  const TriMesh closed = shapes::box(Vec3(0, 0, 2), Vec3(3, 3, 2.25));
  auto only = [&](auto keep) {
    TriMesh m = closed;
    m.faces.erase(std::remove_if(m.faces.begin(), m.faces.end(), [&](const Face& f) { return !keep(m, f); }), m.faces.end());
    return m;
  };
  const TriMesh open = only([](const TriMesh& m, const Face& f) {
    return !(m.vertices[f[0]].x() == 3 && m.vertices[f[1]].x() == 3 && m.vertices[f[2]].x() == 3);
  });
  const TriMesh sheet = only([](const TriMesh& m, const Face& f) {
    return m.vertices[f[0]].z() == 2.25 && m.vertices[f[1]].z() == 2.25 && m.vertices[f[2]].z() == 2.25;
  });
  ASSERT_EQ(open.faces.size(), 10u);
  ASSERT_EQ(sheet.faces.size(), 2u);
  Component c;
  c.hull = shapes::box(Vec3(0.5, 0.5, 2.05), Vec3(2.5, 2.5, 2.2));
  for (const TriMesh* input : {&closed, &open, &sheet}) {
    Decomposition d;
    d.options.tau = 0.05;
    d.normalization = minimumSphereNormalization(closed);  // the same units for all three
    d.components = {c};
    const HullsOffInput off = hullsOffInput(*input, d);
    const double s = d.normalization.scale;
    EXPECT_EQ(off.openShells, input == &closed ? 0 : 1);
    if (input != &sheet) {
      EXPECT_EQ(off.excess[0], 0.0);
      EXPECT_TRUE(off.kept);
    } else {
      EXPECT_LE(off.excess[0], 0.2 * s + 1e-9);
      EXPECT_GE(off.excess[0], 0.95 * 0.2 * s);
      EXPECT_FALSE(off.kept);
    }
  }
}
