// How far a hull stands off its mesh, against shapes whose answer is known in closed form.
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>
#include <acd/algo/working_mesh.hpp>

#include "helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

namespace {

using acd::TriMesh;
using acd::Vec3;

TEST(HullExcess, ConvexMeshHasNone) {
  const TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const acd::HullExcess e = acd::measureHullExcess(box, acd::hullMesh(box.vertices), 0.01, 0.005);
  EXPECT_FALSE(e.exceeds);
  EXPECT_LT(e.distance, 1e-12);
  EXPECT_LE(e.bound, 0.01 + 1e-12);
}

// Below the limit the search only proves "within the limit"; the excess itself is bracketed by
// one limit just under it (a point beyond is found) and one just over it (none can be).
void expectExcessBetween(const TriMesh& mesh, double lo, double hi) {
  const TriMesh hull = acd::hullMesh(mesh.vertices);
  const acd::HullExcess below = acd::measureHullExcess(mesh, hull, lo, 0.001);
  EXPECT_TRUE(below.exceeds);
  EXPECT_GT(below.distance, lo);
  EXPECT_LE(below.distance, hi);
  const acd::HullExcess above = acd::measureHullExcess(mesh, hull, hi, 0.001);
  EXPECT_FALSE(above.exceeds);
  EXPECT_LE(above.distance, hi);
  EXPECT_LE(above.bound, hi + 1e-12);
}

TEST(HullExcess, LShapeStandsOffByHalfACell) {
  // Cells (0,0), (1,0), (0,1): the hull covers the notch x, y in [1, 2], x + y <= 3; its point
  // (1.5, 1.5) on the face across the notch is 0.5 from the faces y = 1 and x = 1, and no hull
  // point is farther from the L.
  const TriMesh l = acd::shapes::lShape();
  expectExcessBetween(l, 0.49, 0.51);
  // The reported points: over the notch, and its nearest surface point, checked with the tests'
  // own distance code.
  const acd::HullExcess e = acd::measureHullExcess(l, acd::hullMesh(l.vertices), 0.45, 0.001);
  ASSERT_TRUE(e.exceeds);
  EXPECT_GE(e.hullPoint.x(), 1.0);
  EXPECT_GE(e.hullPoint.y(), 1.0);
  EXPECT_LE(e.hullPoint.x() + e.hullPoint.y(), 3.0 + 1e-9);
  acdtest::MeshIndex index(l);
  EXPECT_NEAR(index.distance(e.hullPoint), e.distance, 1e-9);
  EXPECT_NEAR((e.hullPoint - e.surfacePoint).norm(), e.distance, 1e-12);
}

TEST(HullExcess, UShapeSlotIsAsDeepAsItIsWide) {
  // The slot (x in [1, 2], y in [1, 3]) is 1 wide and 2 deep. Every hull point over it (the lid
  // y = 3 and the slot's parts of the faces z = 0 and z = 1) is at most 0.5 from a wall x = 1 or
  // x = 2, and the points on the slot's middle plane x = 1.5 are exactly 0.5 from both.
  expectExcessBetween(acd::shapes::uShape(), 0.49, 0.51);
}

TEST(HullExcess, StopsAtTheFirstPointBeyondTheLimit) {
  const TriMesh u = acd::shapes::uShape();
  const acd::HullExcess e = acd::measureHullExcess(u, acd::hullMesh(u.vertices), 0.1, 0.01);
  EXPECT_TRUE(e.exceeds);
  EXPECT_GT(e.distance, 0.1);
  EXPECT_LE(e.distance, 0.5 + 1e-9);
}

// Over the U's slot the hull's lid is 0.5 from the walls along the slot's middle line and closer
// elsewhere. The corners' distance to the nearest wall bounds a patch exactly, so only patches
// astride the middle line are split; the Lipschitz bound alone would split the whole lid to patches
// of radius 0.51 - d.
TEST(HullExcess, FlatStretchesAreSettledWithoutSplittingToTheResolution) {
  const TriMesh u = acd::shapes::uShape();
  const acd::HullExcess e = acd::measureHullExcess(u, acd::hullMesh(u.vertices), 0.51, 1e-6);
  EXPECT_FALSE(e.exceeds);
  EXPECT_LE(e.bound, 0.51 + 1e-12);
  EXPECT_GE(e.distance, 0.5 - 1e-3);  // the corners probed in place of the splits find the middle line
  EXPECT_LT(e.probes, 1000);  // 386; the Lipschitz bound alone: 2732
}

// Against the tests' own distance code on a bumpy sphere: hull points sampled densely never lie
// farther than the bound, a sampled point beyond the limit means the search says so, and the
// reported point is where the reported distance is.
TEST(HullExcess, AgreesWithDenseSamplingOnABumpySphere) {
  TriMesh m = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const std::vector<Vec3> noise = acdtest::randomPoints(static_cast<int>(m.vertices.size()), 7);
  for (std::size_t v = 0; v < m.vertices.size(); ++v) m.vertices[v] *= 1.0 + 0.15 * noise[v].x();
  const TriMesh hull = acd::hullMesh(m.vertices);
  acdtest::MeshIndex index(m);
  double sampled = 0.0;
  const int n = 24;
  for (const acd::Face& f : hull.faces)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 q = hull.vertices[f[0]] + (hull.vertices[f[1]] - hull.vertices[f[0]]) * (double(i) / n) +
                       (hull.vertices[f[2]] - hull.vertices[f[0]]) * (double(j) / n);
        sampled = std::max(sampled, index.distance(q));
      }
  ASSERT_GT(sampled, 0.02);
  for (double limit : {0.5 * sampled, 0.9 * sampled, 1.1 * sampled, 2.0 * sampled}) {
    const acd::HullExcess e = acd::measureHullExcess(m, hull, limit, 1e-4);
    if (sampled > limit) EXPECT_TRUE(e.exceeds) << limit;
    if (!e.exceeds) {
      EXPECT_GE(e.bound, sampled - 1e-12) << limit;
      EXPECT_LE(e.bound, limit + 1e-4 + 1e-12) << limit;  // leaves at the resolution may reach past it
    }
    EXPECT_LE(e.distance, e.bound + 1e-12) << limit;
    EXPECT_NEAR(index.distance(e.hullPoint), e.distance, 1e-9) << limit;
  }
}

}  // namespace

namespace {

using acd::TriMesh;
using acd::Vec3;

// The U's slot again, measured against a finely split copy of the U through the face grid, with
// the U itself as the stand-in that tells inside from outside: the same 0.5.
TEST(InputExcess, UShapeSlotAgainstAFineCopyIsAsDeepAsItIsWide) {
  const TriMesh u = acd::shapes::uShape();
  const TriMesh fine = acdtest::midpointSubdivided(acdtest::midpointSubdivided(acdtest::midpointSubdivided(u)));
  const acd::InputExcess input(fine, u, 0.0);
  const TriMesh hull = acd::hullMesh(u.vertices);
  const acd::HullExcess below = input.measure(hull, 0.49, 0.001);
  EXPECT_TRUE(below.exceeds);
  EXPECT_GT(below.distance, 0.49);
  EXPECT_LE(below.distance, 0.51);
  const acd::HullExcess above = input.measure(hull, 0.51, 0.001);
  EXPECT_FALSE(above.exceeds);
  EXPECT_LE(above.bound, 0.51 + 1e-12);
  // The hull's corners are the U's own: settling short faces by them changes no answer.
  EXPECT_TRUE(input.measure(hull, 0.49, 0.001, -1, 0.0).exceeds);
  const acd::HullExcess settled = input.measure(hull, 0.51, 0.001, -1, 0.0);
  EXPECT_FALSE(settled.exceeds);
  EXPECT_LE(settled.bound, 0.51 + 1e-12);
  // Nor does a search started elsewhere.
  for (int first = 0; first < static_cast<int>(hull.faces.size()); first += 5)
    EXPECT_TRUE(input.measure(hull, 0.49, 0.001, first, 0.0).exceeds) << first;
}

// A dense bumpy sphere against a hull that sticks out of it at its corners and runs through it
// elsewhere, with a coarse stand-in (the working mesh within 0.01): the search agrees with dense
// sampling by the tests' own distance and inside code, where points inside the input count zero.
TEST(InputExcess, AgreesWithDenseSamplingOnADenseBumpySphere) {
  TriMesh m = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 5);
  const std::vector<Vec3> noise = acdtest::randomPoints(static_cast<int>(m.vertices.size()), 3);
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const Vec3 p = m.vertices[v];
    m.vertices[v] *= 1.0 + 0.05 * std::sin(7 * p.x()) * std::cos(5 * p.y()) + 0.002 * noise[v].x();
  }
  const acd::WorkingMesh standIn = acd::simplifyWithin(m, 0.01);
  ASSERT_LT(standIn.mesh.faces.size(), m.faces.size() / 4);
  const acd::InputExcess input(m, standIn.mesh, 2 * std::max(standIn.inputToWorking, 0.01));
  acdtest::MeshIndex index(m);
  // A box through the sphere whose corners stand out of it, and the hull of the sphere's vertices.
  for (const TriMesh& hull : {acd::hullMesh(acd::shapes::box(Vec3(-0.75, -0.7, -0.65), Vec3(0.7, 0.75, 0.7)).vertices),
                              acd::hullMesh(m.vertices)}) {
    // Samples 0.02 apart at most: the excess is 1-Lipschitz, so none is missed by more than that.
    const double spacing = 0.02;
    double sampled = 0.0;
    for (const acd::Face& f : hull.faces) {
      double longest = 0.0;
      for (int k = 0; k < 3; ++k) longest = std::max(longest, (hull.vertices[f[k]] - hull.vertices[f[(k + 1) % 3]]).norm());
      const int n = std::max(2, static_cast<int>(std::ceil(longest / spacing)));
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          const Vec3 q = hull.vertices[f[0]] + (hull.vertices[f[1]] - hull.vertices[f[0]]) * (double(i) / n) +
                         (hull.vertices[f[2]] - hull.vertices[f[0]]) * (double(j) / n);
          if (!index.inside(q)) sampled = std::max(sampled, index.distance(q));
        }
    }
    ASSERT_GT(sampled, 0.005);
    for (double limit : {0.5 * sampled, 0.9 * sampled, 1.1 * sampled, 2.0 * sampled}) {
      const acd::HullExcess e = input.measure(hull, limit, 1e-3);
      if (sampled > limit) EXPECT_TRUE(e.exceeds) << limit;
      if (!e.exceeds) EXPECT_GE(e.bound, sampled - 1e-12) << limit;
      // What it found is a lower bound: no farther than sampling finds anywhere near it.
      EXPECT_LE(e.distance, sampled + spacing) << limit;
      if (sampled + spacing < limit) EXPECT_FALSE(e.exceeds) << limit;
    }
  }
}

}  // namespace

namespace {

using acd::TriMesh;
using acd::Vec3;

void expectSameAnswer(const acd::HullExcess& a, const acd::HullExcess& b, const std::string& what) {
  EXPECT_EQ(a.exceeds, b.exceeds) << what;
  EXPECT_EQ(a.distance, b.distance) << what;
  EXPECT_EQ(a.bound, b.bound) << what;
  EXPECT_EQ(a.hullPoint, b.hullPoint) << what;
  EXPECT_EQ(a.surfacePoint, b.surfacePoint) << what;
  EXPECT_EQ(a.hullFace, b.hullFace) << what;
  EXPECT_EQ(a.probes, b.probes) << what;
}

/// A bumpy sphere, the hull of all its vertices and the hulls of its two halves (which share many
/// faces with the whole one, as the hulls of a union in the merge pass share the parts' faces).
struct Halves {
  TriMesh model, whole, left, right;
  Halves(int subdivisions, double bump) {
    model = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, subdivisions);
    for (Vec3& v : model.vertices) v *= 1.0 + bump * std::sin(7 * v.x()) * std::cos(5 * v.y());
    std::vector<Vec3> l, r;
    for (const Vec3& v : model.vertices) {
      if (v.x() < 0.3) l.push_back(v);
      if (v.x() > -0.3) r.push_back(v);
    }
    whole = acd::hullMesh(model.vertices), left = acd::hullMesh(l), right = acd::hullMesh(r);
  }
};

// A measure remembers the faces it searched to the end; a face met again is not searched again.
// The answer must be the one a fresh measure gives, bit for bit, whatever was measured before.
TEST(ModelExcess, FacesSearchedBeforeGiveTheSameAnswer) {
  const Halves h(3, 0.08);
  for (double limit : {0.01, 0.03, 0.2}) {
    const acd::HullExcess fresh = acd::ModelExcess(h.model).measure(h.whole, limit, 1e-3);
    const acd::ModelExcess used(h.model);
    used.measure(h.left, limit, 1e-3);
    used.measure(h.right, limit, 1e-3);
    expectSameAnswer(used.measure(h.whole, limit, 1e-3), fresh, "after the halves, limit " + std::to_string(limit));
    expectSameAnswer(used.measure(h.whole, limit, 1e-3), fresh, "again, limit " + std::to_string(limit));
    // Another limit or resolution is another search.
    expectSameAnswer(used.measure(h.whole, limit, 2e-3), acd::ModelExcess(h.model).measure(h.whole, limit, 2e-3),
                     "another resolution");
  }
}

TEST(InputExcess, FacesSearchedBeforeGiveTheSameAnswer) {
  const Halves h(4, 0.05);
  const acd::WorkingMesh standIn = acd::simplifyWithin(h.model, 0.01);
  const double standOff = 2 * std::max(standIn.inputToWorking, 0.01);
  for (double limit : {0.01, 0.03, 0.2}) {
    const acd::HullExcess fresh = acd::InputExcess(h.model, standIn.mesh, standOff).measure(h.whole, limit, 1e-3);
    const acd::InputExcess used(h.model, standIn.mesh, standOff);
    used.measure(h.left, limit, 1e-3);
    used.measure(h.right, limit, 1e-3);
    expectSameAnswer(used.measure(h.whole, limit, 1e-3), fresh, "after the halves, limit " + std::to_string(limit));
    expectSameAnswer(used.measure(h.whole, limit, 1e-3), fresh, "again, limit " + std::to_string(limit));
  }
}

// What a merged hull adds outside the model and the hulls it replaces, against volumes known in
// closed form: the estimate (4096 samples) within five standard deviations of a binomial count,
// for several sample streams, straight and turned. The samples a covering hull's planes are
// skipped for (those its corners keep to) must still be counted where they leave it.
void expectAddedVolume(const TriMesh& a, const TriMesh& b, double expected, double hullVolume, const std::string& what) {
  const acd::ModelExcess model(acd::concatenate({a, b}));
  const TriMesh hull = acd::hullMesh([&] {
    std::vector<Vec3> corners = a.vertices;
    corners.insert(corners.end(), b.vertices.begin(), b.vertices.end());
    return corners;
  }());
  const int samples = 4096;
  const double p = expected / hullVolume;
  const double sigma = hullVolume * std::sqrt(p * (1 - p) / samples);
  for (std::uint64_t key : {1u, 7u, 12345u, 99991u, 31337u}) {
    const double added = model.addedVolume(hull, {&a, &b}, samples, key, std::numeric_limits<double>::infinity());
    EXPECT_NEAR(added, expected, 5 * sigma) << what << ", key " << key;
  }
}

TEST(ModelExcess, AddedVolumeCountsTheGapBetweenTwoCubes) {
  // The union's hull is [0,3] x [0,1]^2; the unit gap between the cubes is what it adds. The fan's
  // apex (the hull vertices' centroid) lies in the gap, inside neither cube.
  const TriMesh a = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = acd::shapes::box(Vec3(2, 0, 0), Vec3(3, 1, 1));
  expectAddedVolume(a, b, 1.0, 3.0, "straight");
  std::mt19937_64 rng(5);
  const Eigen::Matrix3d r = acdtest::randomRotation(rng);
  const Vec3 t(0.3, -0.2, 0.1);
  expectAddedVolume(acdtest::moved(a, r, t), acdtest::moved(b, r, t), 1.0, 3.0, "turned");
}

TEST(ModelExcess, AddedVolumeCountsTheCornerOfAnLShape) {
  // A = [0,2] x [0,1] x [0,1], B = [0,1] x [1,2] x [0,1]: their hull adds the prism over the
  // triangle (1,1) (2,1) (1,2), volume 1/2, of a hull of volume 3.5. The apex, (1, 1, 1/2), lies
  // on both boxes, so tetrahedra wholly inside one are skipped; the others hold the triangle.
  const TriMesh a = acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1)), b = acd::shapes::box(Vec3(0, 1, 0), Vec3(1, 2, 1));
  expectAddedVolume(a, b, 0.5, 3.5, "straight");
  std::mt19937_64 rng(11);
  const Eigen::Matrix3d r = acdtest::randomRotation(rng);
  const Vec3 t(-0.4, 0.25, 0.6);
  expectAddedVolume(acdtest::moved(a, r, t), acdtest::moved(b, r, t), 0.5, 3.5, "turned");
}

}  // namespace
