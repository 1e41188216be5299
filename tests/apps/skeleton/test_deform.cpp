// Deformations: the affine one on known volumes, the ARAP bend's handle/fixed invariants,
// spec errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <acd/algo/shapes.hpp>
#include <acd/io.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "deform.hpp"

using namespace skeleton;

namespace {

/// A capsule-like rod along z (radius 0.3, length 4) with a fine enough mesh to bend.
acd::TriMesh rod() {
  return acd::shapes::revolve(
      [](double z) { return 0.3 * std::sqrt(std::max(0.0, 1.0 - std::pow(z / 2.0, 16))) + 1e-3; }, -2.0, 2.0, 80, 16);
}

}  // namespace

TEST(Deform, AffineScalesVolumeAndKeepsOrientation) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const double v = acd::signedVolume(box);
  const acd::TriMesh scaled = affineDeform(box, Vec3(10, 20, 30), Vec3(2, 1, 0.5), Vec3(5, 0, 0));
  EXPECT_NEAR(acd::signedVolume(scaled), v, 1e-9);  // 2 * 1 * 0.5 = 1
  const acd::TriMesh stretched = affineDeform(box, Vec3(0, 0, 0), Vec3(3, 1, 1), Vec3::Zero());
  EXPECT_NEAR(acd::signedVolume(stretched), 3 * v, 1e-9);
  const acd::TriMesh mirrored = affineDeform(box, Vec3(0, 0, 0), Vec3(-1, 1, 1), Vec3::Zero());
  EXPECT_NEAR(acd::signedVolume(mirrored), v, 1e-9);  // faces flipped: still outward
  // Rigid motion keeps every distance.
  const acd::TriMesh moved = affineDeform(box, Vec3(33, -12, 71), Vec3(1, 1, 1), Vec3(1, 2, 3));
  for (std::size_t i = 1; i < box.vertices.size(); ++i)
    EXPECT_NEAR((moved.vertices[i] - moved.vertices[0]).norm(), (box.vertices[i] - box.vertices[0]).norm(), 1e-12);
  // The translation moves the bounding-box centre by exactly (1, 2, 3) under rotation about it.
  EXPECT_LT((acd::boundingBox(moved).center() - acd::boundingBox(box).center() - Vec3(1, 2, 3)).norm(), 0.6);
  const DeformResult r = applyDeformation(box, "affine:0,0,90:1,1,1");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(acd::boundingBox(r.mesh).size().x(), 2.0, 1e-12);  // x and y swap extents
  EXPECT_NEAR(acd::boundingBox(r.mesh).size().y(), 1.0, 1e-12);
}

TEST(Deform, BendMovesTheHandleRigidlyAndKeepsTheRestFixed) {
  const acd::TriMesh mesh = rod();
  const ArapRequest request = bendRequest(mesh, Vec3::UnitZ(), Vec3::UnitX(), 45.0, 0.08, 0.3);
  ASSERT_FALSE(request.handle.empty());
  ASSERT_GT(request.region.size(), request.handle.size());
  // The region's outer ring lies at path distance 0.3 diagonals from the tip: over the rounded
  // end (about one radius) and down the side.
  EXPECT_NEAR(request.pivot.z(), 2.0 - 0.3 * acd::boundingBox(mesh).size().norm() + 0.3, 0.15);
  EXPECT_LT(Vec3(request.pivot.x(), request.pivot.y(), 0).norm(), 0.02);  // a ring around the axis
  const DeformResult r = applyDeformation(mesh, "bend:+z:x:45:0.08:0.3");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.mesh.vertices.size(), mesh.vertices.size());
  EXPECT_EQ(r.mesh.faces, mesh.faces);
  std::vector<char> inRegion(mesh.vertices.size(), 0);
  for (int v : request.region) inRegion[v] = 1;
  for (int v : request.handle) inRegion[v] = 1;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!inRegion[v]) EXPECT_EQ(r.mesh.vertices[v], mesh.vertices[v]);  // fixed exactly
  // Handle vertices reach their rotated targets (hard constraints).
  const Eigen::AngleAxisd rotation(M_PI / 4, Vec3::UnitX());
  double worst = 0;
  for (int v : request.handle) {
    const Vec3 target = request.pivot + rotation * (mesh.vertices[v] - request.pivot);
    worst = std::max(worst, (r.mesh.vertices[v] - target).norm());
  }
  EXPECT_LT(worst, 1e-6);
  // The tip really moved sideways (bent), and the volume stays close (ARAP is near-isometric).
  EXPECT_GT(std::abs(acd::boundingBox(r.mesh).lo.y() - acd::boundingBox(mesh).lo.y()) +
                std::abs(acd::boundingBox(r.mesh).hi.y() - acd::boundingBox(mesh).hi.y()),
            0.3);
  EXPECT_NEAR(acd::signedVolume(r.mesh), acd::signedVolume(mesh), 0.1 * acd::signedVolume(mesh));
}

TEST(Deform, TwistTurnsTheHandleAboutTheLimbsOwnAxis) {
  const acd::TriMesh mesh = rod();
  const DeformResult r = applyDeformation(mesh, "twist:+z:90:0.08:0.3");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.mesh.vertices.size(), mesh.vertices.size());
  // The rod's axis is z and the pivot lies on it, so the twist's axis is z: every handle vertex
  // keeps its height and its distance from the axis, and turns by 90 degrees about it.
  const ArapRequest request = bendRequest(mesh, Vec3::UnitZ(), Vec3::UnitX(), 90.0, 0.08, 0.3);
  int turned = 0;
  for (int v : request.handle) {
    const Vec3 &a = mesh.vertices[v], &b = r.mesh.vertices[v];
    EXPECT_NEAR(a.z(), b.z(), 1e-3);
    EXPECT_NEAR(Vec3(a.x(), a.y(), 0).norm(), Vec3(b.x(), b.y(), 0).norm(), 1e-3);
    if (Vec3(a.x(), a.y(), 0).norm() > 0.1) {
      EXPECT_NEAR(a.x() * b.x() + a.y() * b.y(), 0.0, 1e-3);  // a quarter turn
      ++turned;
    }
  }
  EXPECT_GT(turned, 0);
  // Nothing bends: the bounding box stays (the rod is round).
  EXPECT_LT((acd::boundingBox(r.mesh).size() - acd::boundingBox(mesh).size()).norm(), 0.05);
}

TEST(Deform, ASequenceAppliesEachStepToTheLastResult) {
  const acd::TriMesh mesh = rod();
  const DeformResult both = applyDeformation(mesh, "affine:0,0,0:2,1,1;affine:0,0,0:1,3,1");
  ASSERT_TRUE(both.ok) << both.error;
  EXPECT_NEAR(acd::signedVolume(both.mesh), 6 * acd::signedVolume(mesh), 1e-9);
  EXPECT_NE(both.summary.find("; then "), std::string::npos);
  const DeformResult bent = applyDeformation(mesh, "bend:+z:x:20:0.2:0.45;bend:+z:x:20");
  ASSERT_TRUE(bent.ok) << bent.error;
  EXPECT_EQ(bent.mesh.faces, mesh.faces);
}

TEST(Deform, GivenVertexIds) {
  const acd::TriMesh mesh = rod();
  const std::string path = testing::TempDir() + "skeleton_ids_" + std::to_string(::getpid()) + ".json";
  {
    std::ofstream out(path);
    out << R"({"handle": [0], "region": [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17],
               "pivot": [0, 0, 0], "axis": [0, 0, 1], "angle": 90})";
  }
  const DeformResult r = applyDeformation(mesh, "ids:" + path);
  std::remove(path.c_str());
  ASSERT_TRUE(r.ok) << r.error;
  const Vec3 expected = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) * mesh.vertices[0];
  EXPECT_LT((r.mesh.vertices[0] - expected).norm(), 1e-6);
  EXPECT_EQ(r.mesh.vertices[40], mesh.vertices[40]);
}

TEST(Deform, BadSpecsAreNamed) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const struct {
    const char* spec;
    const char* words;
  } cases[] = {
      {"shear:1", "unknown deformation 'shear'"},
      {"twist:+x", "twist needs"},
      {"twist:+q:30", "twist direction"},
      {"bend:+x:z:30;shear:2", "unknown deformation 'shear'"},
      {"bend:+w:x:30", "bend direction"},
      {"bend:+x:q:30", "bend axis"},
      {"bend:+x:z:abc", "not a number"},
      {"bend:+x:z:30:0.5:0.2", "region radius"},
      {"bend:+x", "bend needs"},
      {"affine:1,2:1,1,1", "rotation needs three numbers"},
      {"affine:0,0,0:1,0,1", "must not be zero"},
      {"ids:/nonexistent/file.json", "cannot open"},
  };
  for (const auto& c : cases) {
    const DeformResult r = applyDeformation(box, c.spec);
    EXPECT_FALSE(r.ok) << c.spec;
    EXPECT_NE(r.error.find(c.words), std::string::npos) << c.spec << " -> " << r.error;
  }
  ArapRequest outOfRange;
  outOfRange.handle = {100};
  const ArapResult a = arapDeform(box, outOfRange);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.error.find("vertex id 100 out of range"), std::string::npos) << a.error;
}
