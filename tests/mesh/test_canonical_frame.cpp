// The canonical frame moves with the shape: a rigid motion, a reordering of vertices or faces
// gives the same canonical mesh, bit for bit.
#include <acd/algo/canonical_frame.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using acd::TriMesh;
using acd::Vec3;
using acdtest::moved;
using acdtest::randomRotation;

/// Unit cells in an L with a tower and a stub: mirror symmetric about the plane x = z (so one of
/// its third moments vanishes), no two equal principal moments.
TriMesh mirrorSymmetricShape() {
  return acd::shapes::voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 2}, {1, 0, 1}});
}

/// The same with one more cell that breaks the mirror symmetry.
TriMesh asymmetricShape() {
  TriMesh m = acd::shapes::voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 2}, {1, 0, 1}, {0, 1, 1}});
  return m;
}


/// The same solid with vertices renumbered and faces shuffled (and each face's corners rotated).
TriMesh shuffled(const TriMesh& m, std::mt19937_64& rng) {
  std::vector<int> perm(m.vertices.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  TriMesh out;
  out.vertices.resize(m.vertices.size());
  for (std::size_t v = 0; v < perm.size(); ++v) out.vertices[perm[v]] = m.vertices[v];
  for (const acd::Face& f : m.faces) {
    acd::Face g{perm[f[0]], perm[f[1]], perm[f[2]]};
    std::rotate(g.begin(), g.begin() + static_cast<int>(rng() % 3), g.end());
    out.faces.push_back(g);
  }
  std::shuffle(out.faces.begin(), out.faces.end(), rng);
  return out;
}

void expectSameMesh(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t v = 0; v < a.vertices.size(); ++v) EXPECT_EQ(a.vertices[v], b.vertices[v]) << "vertex " << v;
  EXPECT_TRUE(a.faces == b.faces);
}

TEST(MinimumSphere, SameRadiusInEveryPoseAndNoPointOutside) {
  // The radius is the unit of tau: it must not depend on the pose. CGAL's default solver missed
  // a point for about 3% of these poses (radius 1.95 instead of 2.23).
  const TriMesh shape = asymmetricShape();
  const double radius = 1.0 / acd::minimumSphereNormalization(shape).scale;
  std::mt19937_64 rng(0);
  std::normal_distribution<double> g;
  for (int pose = 0; pose < 200; ++pose) {
    const Eigen::Matrix3d rotation = randomRotation(rng);
    const TriMesh m = moved(shape, rotation, acdtest::drawPoint([&] { return g(rng); }) * (pose % 2 ? 1.0 : 1e3));
    const acd::Normalization n = acd::minimumSphereNormalization(m);
    EXPECT_NEAR(1.0 / n.scale, radius, 1e-12 * (pose % 2 ? 1.0 : 1e3)) << "pose " << pose;
    for (const Vec3& p : m.vertices) EXPECT_LE((p - n.center).norm(), 1.0 / n.scale * (1 + 1e-15)) << "pose " << pose;
  }
  // Independent bounds from the shape's diameter d: d / 2 <= r <= d sqrt(3/8) (Jung's theorem).
  double diameter = 0;
  for (const Vec3& a : shape.vertices)
    for (const Vec3& b : shape.vertices) diameter = std::max(diameter, (a - b).norm());
  EXPECT_GE(radius, 0.5 * diameter - 1e-12);
  EXPECT_LE(radius, diameter * std::sqrt(3.0 / 8.0) + 1e-12);
}

TEST(CanonicalFrame, IsAProperRotation) {
  const acd::Normalization n = acd::canonicalFrame({asymmetricShape()});
  EXPECT_LT((n.rotation * n.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(n.rotation.determinant(), 1.0, 1e-12);
}

TEST(CanonicalFrame, FirstAxisIsTheLongSideOfABox) {
  // Surface second moments of a 1 x 2 x 3 box (independent: they only need ordering): the
  // spread is largest along the 3-long side, smallest along the 1-long side.
  const acd::Normalization n = acd::canonicalFrame({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3))});
  EXPECT_NEAR(std::abs(n.rotation.row(0).dot(Vec3::UnitZ().transpose())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(n.rotation.row(1).dot(Vec3::UnitY().transpose())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(n.rotation.row(2).dot(Vec3::UnitX().transpose())), 1.0, 1e-12);
  // Units of the minimum enclosing sphere: the half diagonal of the box.
  EXPECT_NEAR(n.scale, 1.0 / (0.5 * std::sqrt(14.0)), 1e-12);
  EXPECT_LT((n.center - Vec3(0.5, 1.0, 1.5)).norm(), 1e-12);
}

TEST(CanonicalFrame, EqualMomentsGiveAxesAlongTheFaces) {
  // A 1 x 1 x 3 box (two equal moments) and a cube (three): moments alone leave the axes free;
  // the frame takes them along the faces, in any pose. Checked: every canonical axis is parallel
  // to one of the box's edge directions, moved by the same rotation.
  std::mt19937_64 rng(5);
  for (const Vec3& size : {Vec3(1, 1, 3), Vec3(2, 2, 2), Vec3(3, 1, 1)}) {
    for (int pose = 0; pose < 5; ++pose) {
      const Eigen::Matrix3d r = pose == 0 ? Eigen::Matrix3d::Identity() : randomRotation(rng);
      const TriMesh box = moved(acd::shapes::box(Vec3(0, 0, 0), size), r, Vec3(0.5, -2.0, 1.0));
      const acd::Normalization n = acd::canonicalFrame({box});
      for (int axis = 0; axis < 3; ++axis) {
        double best = 0;
        for (int k = 0; k < 3; ++k) best = std::max(best, std::abs(n.rotation.row(axis).dot(r.col(k).transpose())));
        EXPECT_NEAR(best, 1.0, 1e-9) << "box " << size.transpose() << " pose " << pose << " axis " << axis;
      }
    }
  }
}

class CanonicalFrameMotion : public ::testing::TestWithParam<bool> {};

TEST_P(CanonicalFrameMotion, RigidMotionsGiveTheSameCanonicalMesh) {
  const TriMesh shape = GetParam() ? mirrorSymmetricShape() : asymmetricShape();
  const acd::CanonicalMesh reference = acd::canonicalMesh(shape, acd::canonicalFrame({shape}));
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("motion " + std::to_string(trial));
    const double size = trial < 5 ? 1.0 : 1e3;  // also far from the origin
    std::uniform_real_distribution<double> u(-size, size);
    const Eigen::Matrix3d rotation = randomRotation(rng);
    const TriMesh m = moved(shape, rotation, acdtest::drawPoint([&] { return u(rng); }));
    expectSameMesh(acd::canonicalMesh(m, acd::canonicalFrame({m})).mesh, reference.mesh);
  }
  const TriMesh nudged = moved(shape, Eigen::Matrix3d::Identity(), Vec3(1e-12, -1e-12, 1e-9));
  expectSameMesh(acd::canonicalMesh(nudged, acd::canonicalFrame({nudged})).mesh, reference.mesh);
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const TriMesh turned = moved(shape, quarter, Vec3::Zero());
  expectSameMesh(acd::canonicalMesh(turned, acd::canonicalFrame({turned})).mesh, reference.mesh);
}

INSTANTIATE_TEST_SUITE_P(Shapes, CanonicalFrameMotion, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "MirrorSymmetric" : "Asymmetric"; });

// Nearly equal moments: their eigenvectors turn by the rounding error over the gap when the shape
// moves, enough to move coordinates across a step of the canonical grid. The frame treats them as
// equal (the faces' normals decide), so every pose gives the same canonical mesh bit for bit. The
// knot of the corpus: its two largest moments are 2.1e-6 apart; with the old tolerance of 1e-8,
// two of the ten poses of bench/invariance.sh gave it other parts at tau 0.1.
TEST(CanonicalFrame, NearlyEqualMomentsGiveTheSameCanonicalMeshInEveryPose) {
  const acd::ReadResult knot = acd::readMesh(acdtest::corpus("knot"));
  if (!knot.status.ok()) GTEST_SKIP() << acdtest::corpus("knot") << " not present (scripts/fetch_corpus.sh)";
  const acd::CanonicalMesh reference = acd::canonicalMesh(knot.mesh, acd::canonicalFrame({knot.mesh}));
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("motion " + std::to_string(trial));
    const TriMesh m = moved(knot.mesh, randomRotation(rng), acdtest::drawPoint([&] { return u(rng); }));
    expectSameMesh(acd::canonicalMesh(m, acd::canonicalFrame({m})).mesh, reference.mesh);
  }
}

TEST(CanonicalFrame, OrderOfVerticesAndFacesDoesNotShow) {
  const TriMesh shape = asymmetricShape();
  const acd::CanonicalMesh reference = acd::canonicalMesh(shape, acd::canonicalFrame({shape}));
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const TriMesh m = shuffled(shape, rng);
    expectSameMesh(acd::canonicalMesh(m, acd::canonicalFrame({m})).mesh, reference.mesh);
  }
}

TEST(CanonicalFrame, CanonicalMeshKeepsTheSurface) {
  const TriMesh shape = asymmetricShape();
  const acd::Normalization n = acd::canonicalFrame({shape});
  const acd::CanonicalMesh c = acd::canonicalMesh(shape, n);
  // Every canonical vertex is its source vertex moved into the frame, to within the grid.
  for (std::size_t v = 0; v < c.mesh.vertices.size(); ++v)
    EXPECT_LE((c.mesh.vertices[v] - n.apply(shape.vertices[c.source[v]])).cwiseAbs().maxCoeff(),
              0.5 * acd::kCanonicalGrid);
  // Volume in the frame: the input's volume times scale^3 (rotations keep volume and orientation).
  EXPECT_NEAR(acd::signedVolume(c.mesh), acd::signedVolume(shape) * std::pow(n.scale, 3), 1e-5);
  EXPECT_TRUE(acd::isClosedOriented(c.mesh));
}

TEST(CanonicalFrame, CanonicalLessIsAStrictOrder) {
  const TriMesh a = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 2));
  EXPECT_FALSE(acd::canonicalLess(a, a));
  EXPECT_NE(acd::canonicalLess(a, b), acd::canonicalLess(b, a));
}

}  // namespace

// Two or three mirror planes (as CAD parts often have) make two or three third moments vanish,
// and equal second moments leave turns in a plane: the frame is then one of several candidates
// that differ by a symmetry of the geometry, not of the triangulation (a box's faces are split
// along one diagonal each). The candidate in which the mesh reads first is taken: the same
// canonical mesh bit for bit in every pose. (Rounding used to choose: a generated bearing block
// gave 23 or 24 parts in 10 poses, an exact quarter turn included.)
TEST(CanonicalFrame, SymmetricShapesGiveTheSameCanonicalMeshInEveryPose) {
  const std::vector<std::pair<std::string, TriMesh>> shapes = {
      {"box 1x2x3 (three mirror planes)", acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3))},
      {"box 2x2x1 (a square: turns and signs)", acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 1))},
      {"U of cells (two mirror planes)", acd::shapes::uShape()},
      {"subdivided box", acdtest::midpointSubdivided(acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3)))}};
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  for (const auto& [name, shape] : shapes) {
    SCOPED_TRACE(name);
    const acd::CanonicalMesh reference = acd::canonicalMesh(shape, acd::canonicalFrame({shape}));
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    for (int trial = 0; trial < 10; ++trial) {
      SCOPED_TRACE("motion " + std::to_string(trial));
      const TriMesh m = moved(shape, randomRotation(rng), acdtest::drawPoint([&] { return u(rng); }));
      expectSameMesh(acd::canonicalMesh(m, acd::canonicalFrame({m})).mesh, reference.mesh);
    }
    const TriMesh turned = moved(shape, quarter, Vec3::Zero());
    expectSameMesh(acd::canonicalMesh(turned, acd::canonicalFrame({turned})).mesh, reference.mesh);
  }
}

// An L of two plates, whose principal axes are turned in the plane of the L: in the face-aligned
// frame every plane of the L has one coordinate, exactly, after rounding to the grid, in every pose.
TEST(FaceAlignedFrame, PlanesOfACadPartKeepOneCoordinateInEveryPose) {
  const std::vector<TriMesh> parts = {acd::shapes::box(Vec3(0, 0, 0), Vec3(4, 1, 1)),
                                      acd::shapes::box(Vec3(0, 1, 0), Vec3(1, 3, 1))};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("motion " + std::to_string(trial));
    const Eigen::Matrix3d r = randomRotation(rng);
    const Vec3 t = acdtest::drawPoint([&] { return u(rng); });
    std::vector<TriMesh> pose;
    for (const TriMesh& m : parts) pose.push_back(moved(m, r, t));
    const acd::Normalization canonical = acd::canonicalFrame(pose);
    const acd::Normalization aligned = acd::faceAlignedFrame(pose, canonical);
    // Each axis of the aligned frame along one of the part's own axes (the columns of r).
    for (int k = 0; k < 3; ++k) {
      const double along = (r.transpose() * aligned.rotation.row(k).transpose()).cwiseAbs().maxCoeff();
      EXPECT_GT(along, 1.0 - 1e-12) << "axis " << k;
    }
    // The vertices with one original x (y, z) share one rounded coordinate in the aligned frame.
    std::vector<acd::CanonicalMesh> rounded;
    for (const TriMesh& m : pose) rounded.push_back(acd::canonicalMesh(m, aligned));
    for (int axis = 0; axis < 3; ++axis) {
      int frameAxis = 0;  // the aligned frame's axis along the part's own `axis`
      (aligned.rotation * r.col(axis)).cwiseAbs().maxCoeff(&frameAxis);
      std::map<double, std::set<double>> byPlane;  // original coordinate -> rounded coordinates seen
      for (std::size_t p = 0; p < parts.size(); ++p)
        for (std::size_t v = 0; v < rounded[p].source.size(); ++v)
          byPlane[parts[p].vertices[rounded[p].source[v]][axis]].insert(rounded[p].mesh.vertices[v][frameAxis]);
      for (const auto& [plane, seen] : byPlane) EXPECT_EQ(seen.size(), 1u) << "axis " << axis << " plane " << plane;
    }
    // The plain canonical frame is turned in the plane of the L: x = 1 is not one of its planes.
    EXPECT_LT((r.transpose() * canonical.rotation.row(0).transpose()).cwiseAbs().maxCoeff(), 1.0 - 1e-6);
  }
}

TEST(FaceAlignedFrame, ACurvedSurfaceKeepsTheCanonicalFrame) {
  const TriMesh ball = acd::shapes::icosphere(Vec3(0.3, 0.1, -0.2), 2.0, 2);
  const acd::Normalization canonical = acd::canonicalFrame({ball});
  const acd::Normalization aligned = acd::faceAlignedFrame({ball}, canonical);
  EXPECT_TRUE(aligned.rotation == canonical.rotation);
  EXPECT_EQ(aligned.center, canonical.center);
  EXPECT_EQ(aligned.scale, canonical.scale);
}
