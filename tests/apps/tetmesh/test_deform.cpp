// The deformation demo: embedding a surface in a tet mesh, the ARAP solve, and the command.
#include "arap_deform.hpp"
#include "deformation_demo.hpp"
#include "helpers.hpp"
#include "hull_mesher.hpp"
#include "surface_embedding.hpp"
#include "tet_checks.hpp"
#include "tetgen_run.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

using namespace tetmesh;

namespace {

/// The box [0, length] x [0, 1] x [0, 1] meshed by TetGen with quality and a volume bound.
TetMesh barMesh(double length, double maxVolume) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(length, 1, 1));
  Plc plc;
  plc.points = box.vertices;
  for (const acd::Face& f : box.faces) plc.facets.push_back({{f[0], f[1], f[2]}, kBoundaryFacet});
  TetGenOptions o;
  o.radiusEdge = 1.5;
  o.maxVolume = maxVolume;
  o.regions = false;
  const TetGenResult r = runTetGen(plc, o);
  EXPECT_TRUE(r.ok) << r.error;
  return r.mesh;
}

/// Pure bending of the bar about the y axis into a quarter circle whose centre line (z = 0.5)
/// keeps its length: the point at arc length s and height h above the centre line goes to
/// radius (radius - h) at angle s / radius. Rigid on each cross-section.
Vec3 bend(const Vec3& p, double radius) {
  const double phi = p.x() / radius, h = p.z() - 0.5;
  return Vec3((radius - h) * std::sin(phi), p.y(), 0.5 + radius - (radius - h) * std::cos(phi));
}

struct BarSetup {
  TetMesh mesh;
  std::vector<int> constrained;
  std::vector<Vec3> targets;
  int handle = 0;  // the first `handle` constraints are the moved end, the rest the fixed end
};

/// The bar with the end x = length moved by `motion` and the end x = 0 by `fixedEnd`.
template <typename Motion, typename FixedEnd>
BarSetup barWithEnds(double length, double maxVolume, Motion motion, FixedEnd fixedEnd) {
  BarSetup s;
  s.mesh = barMesh(length, maxVolume);
  for (int v = 0; v < static_cast<int>(s.mesh.points.size()); ++v)
    if (s.mesh.points[v].x() == length) s.constrained.push_back(v), s.targets.push_back(motion(s.mesh.points[v]));
  s.handle = static_cast<int>(s.constrained.size());
  for (int v = 0; v < static_cast<int>(s.mesh.points.size()); ++v)
    if (s.mesh.points[v].x() == 0) s.constrained.push_back(v), s.targets.push_back(fixedEnd(s.mesh.points[v]));
  return s;
}

/// The bar with the end x = 0 at rest and the end x = length moved by `motion`.
template <typename Motion>
BarSetup barWithEnds(double length, double maxVolume, Motion motion) {
  return barWithEnds(length, maxVolume, motion, [](const Vec3& p) { return p; });
}

double polylineLength(const std::vector<Vec3>& p) {
  double sum = 0;
  for (std::size_t i = 1; i < p.size(); ++i) sum += (p[i] - p[i - 1]).norm();
  return sum;
}

HullMeshResult meshElephant(Mesher mesher) {
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  EXPECT_TRUE(read.status.ok()) << read.status.message;
  HullMeshOptions o;
  o.tau = 0.2;
  o.threads = 1;
  o.mesher = mesher;
  return meshHulls(read.mesh, o);
}

/// The elephant's hull meshes at tau 0.2, made once for the tests that use them: the refined
/// regions (the default) and the exact complex of the hulls, which contains the model.
const HullMeshResult& elephantMesh(Mesher mesher = Mesher::Refine) {
  static const HullMeshResult refined = meshElephant(Mesher::Refine);
  static const HullMeshResult complex = meshElephant(Mesher::Complex);
  const HullMeshResult& r = mesher == Mesher::Refine ? refined : complex;
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r;
}

}  // namespace

TEST(SurfaceEmbed, ElephantSurfaceIsRecoveredAndFollowsAffineMaps) {
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  const HullMeshResult& r = elephantMesh(Mesher::Complex);
  ASSERT_TRUE(r.status.ok());
  const TetMesh& m = r.mesh;
  const acd::Box3 box = acd::boundingBox(read.mesh);
  const double size = (box.hi - box.lo).norm();
  const SurfaceEmbedding e = embedPoints(m, read.mesh.vertices);
  ASSERT_EQ(e.tet.size(), read.mesh.vertices.size());
  // The hulls contain the model: a vertex lies at most a rounding distance outside.
  EXPECT_LE(e.maxOutsideDistance, 1e-9 * size);
  EXPECT_LT(e.outside, static_cast<int>(read.mesh.vertices.size()));
  // Interpolating the rest positions gives every vertex back.
  const std::vector<Vec3> back = interpolate(e, m, m.points);
  double worst = 0;
  for (std::size_t i = 0; i < back.size(); ++i) {
    ASSERT_GE(e.tet[i], 0);
    double sum = 0;
    for (double w : e.weights[i]) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    worst = std::max(worst, (back[i] - read.mesh.vertices[i]).norm());
  }
  EXPECT_LE(worst, 1e-9 * size) << "largest error " << worst;
  // Linear interpolation is exact for an affine map of the mesh.
  Eigen::Matrix3d a;
  a << 1.2, 0.3, -0.1, 0.05, 0.8, 0.4, -0.2, 0.1, 1.5;
  const Vec3 shift(0.3, -2.0, 1.0);
  std::vector<Vec3> moved(m.points.size());
  for (std::size_t v = 0; v < m.points.size(); ++v) moved[v] = a * m.points[v] + shift;
  const std::vector<Vec3> carried = interpolate(e, m, moved);
  worst = 0;
  for (std::size_t i = 0; i < carried.size(); ++i) worst = std::max(worst, (carried[i] - (a * read.mesh.vertices[i] + shift)).norm());
  EXPECT_LE(worst, 1e-9 * size) << "largest error " << worst;
}

TEST(SurfaceEmbed, TheRefinedMeshFollowsTheModelWithinTau) {
  // The refinement rounds the regions' sharp edges (within about its facet distance, a quarter
  // of tau), so some of the model's vertices lie outside the mesh, but none farther than tau
  // (normalised units): measured by the embedding's own closest-tet search.
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  const HullMeshResult& r = elephantMesh(Mesher::Refine);
  ASSERT_TRUE(r.status.ok());
  const SurfaceEmbedding e = embedPoints(r.mesh, read.mesh.vertices);
  const double tau = 0.2 / r.decomposition.normalization.scale;
  EXPECT_LE(e.maxOutsideDistance, tau);
  std::printf("[ refined  ] %d of %zu model vertices outside the mesh, the farthest %.3g (tau %.3g)\n", e.outside,
              read.mesh.vertices.size(), e.maxOutsideDistance, tau);
}

TEST(SurfaceEmbed, PointsOutsideAreCarriedByTheClosestTet) {
  const TetMesh bar = barMesh(4.0, 0.05);
  ASSERT_FALSE(bar.tets.empty());
  const std::vector<Vec3> points = {
      Vec3(5.0, 0.5, 0.5),     // 1 beyond the end face: closest (4, 0.5, 0.5)
      Vec3(-0.5, -0.5, 0.3),   // beside the edge x = 0, y = 0: closest (0, 0, 0.3)
      Vec3(100, 100, 100),     // far away: closest the corner (4, 1, 1)
      Vec3(1.25, 0.5, 0.75),   // inside
      Vec3(4.0, 1.0, 1.0),     // a corner
      Vec3(2.0, 0.0, 0.5),     // on a side
  };
  const SurfaceEmbedding e = embedPoints(bar, points);
  EXPECT_EQ(e.outside, 3);
  EXPECT_NEAR(e.maxOutsideDistance, (Vec3(100, 100, 100) - Vec3(4, 1, 1)).norm(), 1e-9);
  // At rest every point stays where it is, inside or not; the closest tet holds the closest point.
  const std::vector<Vec3> closest = {Vec3(4, 0.5, 0.5), Vec3(0, 0, 0.3), Vec3(4, 1, 1), points[3], points[4], points[5]};
  const std::vector<Vec3> at = interpolate(e, bar, bar.points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LE((at[i] - points[i]).norm(), 1e-9 * (1 + points[i].norm())) << "point " << i << ": " << at[i].transpose();
    const auto& q = bar.tets[e.tet[i]];
    const Vec3 c = closestPointInTet(points[i], bar.points[q[0]], bar.points[q[1]], bar.points[q[2]], bar.points[q[3]]);
    EXPECT_LE((c - closest[i]).norm(), 1e-9) << "point " << i;
    double sum = 0.0;
    for (double w : e.weights[i]) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  // A rigid motion of the mesh moves every point rigidly, the far ones too.
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vec3 shift(0.3, -1.0, 2.0);
  std::vector<Vec3> moved;
  for (const Vec3& p : bar.points) moved.push_back(q * p + shift);
  const std::vector<Vec3> after = interpolate(e, bar, moved);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_LE((after[i] - (q * points[i] + shift)).norm(), 1e-9 * (1 + points[i].norm())) << "point " << i;
}

TEST(ArapDeform, ConstraintsMovedRigidlyMoveEverythingRigidly) {
  const Eigen::Matrix3d q = Eigen::AngleAxisd(2.0 * M_PI / 3.0, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(1.0, -0.5, 2.0);
  const auto rigid = [&](const Vec3& p) { return Vec3(q * p + t); };
  const BarSetup s = barWithEnds(3.0, 0.05, rigid, rigid);
  for (bool linearStart : {true, false}) {
    ArapOptions o;
    o.linearStart = linearStart;
    o.tolerance = 0;
    o.maxIterations = 500;
    const ArapResult r = arapDeform(s.mesh, s.constrained, s.targets, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    double worst = 0;
    for (std::size_t v = 0; v < s.mesh.points.size(); ++v) worst = std::max(worst, (r.positions[v] - (q * s.mesh.points[v] + t)).norm());
    EXPECT_LE(worst, 1e-6) << (linearStart ? "linear start" : "rest start") << ", " << r.iterations << " iterations";
    EXPECT_LE(r.energy.back(), 1e-12);
    EXPECT_EQ(r.invertedTets, 0);
    EXPECT_NEAR(r.volume, r.restVolume, 1e-9 * r.restVolume);
    if (!linearStart) {
      EXPECT_GT(r.energy.front(), 1e-3);  // the rest start is far from rigid
    }
  }
}

TEST(ArapDeform, EnergyNeverIncreases) {
  const double length = 4.0, radius = 2.0 * length / M_PI;
  const BarSetup s = barWithEnds(length, 0.02, [&](const Vec3& p) { return bend(p, radius); });
  for (bool linearStart : {true, false}) {
    ArapOptions o;
    o.linearStart = linearStart;
    o.tolerance = 0;
    o.maxIterations = 60;
    const ArapResult r = arapDeform(s.mesh, s.constrained, s.targets, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    ASSERT_EQ(r.energy.size(), 61u);
    for (std::size_t i = 1; i < r.energy.size(); ++i)
      EXPECT_LE(r.energy[i], r.energy[i - 1] * (1 + 1e-12)) << "iteration " << i;
    EXPECT_LT(r.energy.back(), 0.5 * r.energy.front());
  }
}

TEST(ArapDeform, BentBarKeepsItsLengthAndVolumeBetterThanTheLinearSolve) {
  // Bar 4 x 1 x 1; one end fixed, the other turned by 90 degrees and placed where a quarter
  // circle of the bar's length would put it.
  const double length = 4.0, radius = 2.0 * length / M_PI;
  const BarSetup s = barWithEnds(length, 0.02, [&](const Vec3& p) { return bend(p, radius); });
  ASSERT_GT(s.handle, 3);
  ASSERT_GT(static_cast<int>(s.constrained.size()), s.handle + 3);
  const ArapResult r = arapDeform(s.mesh, s.constrained, s.targets);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.converged);
  // Constraints hold exactly: they are eliminated from the system, not penalised.
  for (std::size_t i = 0; i < s.constrained.size(); ++i) EXPECT_EQ(r.positions[s.constrained[i]], s.targets[i]);
  EXPECT_EQ(r.maxConstraintError, 0.0);
  EXPECT_EQ(r.invertedTets, 0);
  // Volume: pure bending keeps the volume exactly; ARAP stays close, the linear solve shrinks
  // the bent middle (it interpolates the end positions without turning the cross-sections).
  // Measured: ARAP -1.50%, linear -36.3%; the centre line 4.005 and 3.601 (rest 4).
  const double arapChange = std::abs(r.volume - r.restVolume) / r.restVolume;
  const double linearChange = std::abs(r.linearVolume - r.restVolume) / r.restVolume;
  EXPECT_LT(arapChange, 0.02);
  EXPECT_GT(linearChange, 3 * arapChange);
  // Length of the centre line, carried by the embedding: ARAP keeps it, the linear solve cuts
  // the corner. The middle of the line lies near the quarter circle's middle.
  std::vector<Vec3> line;
  for (int i = 0; i <= 40; ++i) line.emplace_back(length * i / 40.0, 0.5, 0.5);
  const SurfaceEmbedding e = embedPoints(s.mesh, line);
  EXPECT_EQ(e.outside, 0);
  const std::vector<Vec3> arapLine = interpolate(e, s.mesh, r.positions);
  const std::vector<Vec3> linearLine = interpolate(e, s.mesh, r.linearPositions);
  const double arapLength = polylineLength(arapLine), linearLength = polylineLength(linearLine);
  EXPECT_NEAR(arapLength, length, 0.03 * length);
  EXPECT_LT(linearLength, length - 3 * std::abs(arapLength - length));
  EXPECT_LT((arapLine[20] - bend(line[20], radius)).norm(), 0.05 * length);
  // The local step's threads share out the tets; the result is the same bit for bit.
  ArapOptions threaded;
  threaded.threads = 3;
  EXPECT_EQ(arapDeform(s.mesh, s.constrained, s.targets, threaded).positions, r.positions);
  std::printf("[ bar      ] volume change ARAP %.4f%%, linear %.4f%%; centre line ARAP %.4f, linear %.4f (rest %.1f); "
              "middle off the arc by %.4f; %d iterations, energy %.4g -> %.4g\n",
              100 * (r.volume - r.restVolume) / r.restVolume, 100 * (r.linearVolume - r.restVolume) / r.restVolume,
              arapLength, linearLength, length, (arapLine[20] - bend(line[20], radius)).norm(), r.iterations,
              r.energy.front(), r.energy.back());
}

TEST(ArapDeform, TheRefinedMeshInvertsNoMoreTetsThanTheComplex) {
  // The unrefined complex of the elephant's hulls has slivers (dihedral angles near 0); the
  // refined mesh has none below 5 degrees. Turned by 30 degrees with pure volume weights (no
  // floor, which would hide the difference), the refined mesh inverts no more tets.
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  DeformationOptions o;
  o.rotate = true;
  o.angleDegrees = 30;
  o.arap.minWeight = 0;
  const DeformationResult refined = deformSurface(elephantMesh(Mesher::Refine).mesh, read.mesh, o);
  const DeformationResult complex = deformSurface(elephantMesh(Mesher::Complex).mesh, read.mesh, o);
  ASSERT_TRUE(refined.status.ok()) << refined.status.message;
  ASSERT_TRUE(complex.status.ok()) << complex.status.message;
  EXPECT_EQ(elephantMesh(Mesher::Refine).quality.slivers, 0);
  EXPECT_GT(elephantMesh(Mesher::Complex).quality.slivers, 0);
  EXPECT_LE(refined.arap.invertedTets, complex.arap.invertedTets);
  std::printf("[ inverted ] refined %d of %zu tets, complex %d of %zu\n", refined.arap.invertedTets,
              elephantMesh(Mesher::Refine).mesh.tets.size(), complex.arap.invertedTets,
              elephantMesh(Mesher::Complex).mesh.tets.size());
}

TEST(ArapDeform, WeightFloorKeepsSliversFromInverting) {
  // The unrefined complex of the elephant's hulls has slivers (dihedral angles near 0). With pure
  // volume weights some of them can invert when the trunk turns by 30 degrees (3 measured on
  // an earlier version of the complex, 0 on the current one); with the default floor (0.1 x
  // the mean tet volume) none does, and the surface moves alike.
  const HullMeshResult& mesh = elephantMesh(Mesher::Complex);
  ASSERT_TRUE(mesh.status.ok());
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  DeformationOptions o;
  o.rotate = true;
  o.angleDegrees = 30;
  const DeformationResult floored = deformSurface(mesh.mesh, read.mesh, o);
  o.arap.minWeight = 0;
  const DeformationResult pure = deformSurface(mesh.mesh, read.mesh, o);
  ASSERT_TRUE(floored.status.ok() && pure.status.ok());
  EXPECT_EQ(floored.arap.invertedTets, 0);
  EXPECT_LE(floored.arap.invertedTets, pure.arap.invertedTets);
  double apart = 0;
  for (std::size_t i = 0; i < read.mesh.vertices.size(); ++i)
    apart = std::max(apart, (floored.surfaceAfter.vertices[i] - pure.surfaceAfter.vertices[i]).norm());
  EXPECT_LT(apart, 0.1 * floored.maxSurfaceDisplacement);
  std::printf("[ floor    ] inverted tets %d with the floor, %d without; surfaces apart by %.3g (moved up to %.3g)\n",
              floored.arap.invertedTets, pure.arap.invertedTets, apart, floored.maxSurfaceDisplacement);
}

TEST(ArapDeform, UnreachedPartsStayAtRestAndBadConstraintsAreRefused) {
  // Two bars side by side in one mesh, constraints on the first only.
  TetMesh m = barMesh(2.0, 0.1);
  const int base = static_cast<int>(m.points.size()), tets = static_cast<int>(m.tets.size());
  for (int v = 0; v < base; ++v) m.points.push_back(m.points[v] + Vec3(0, 3, 0));
  for (int t = 0; t < tets; ++t) m.tets.push_back({m.tets[t][0] + base, m.tets[t][1] + base, m.tets[t][2] + base, m.tets[t][3] + base});
  std::vector<int> constrained;
  std::vector<Vec3> targets;
  for (int v = 0; v < base; ++v)
    if (m.points[v].x() == 0 || m.points[v].x() == 2.0) constrained.push_back(v), targets.push_back(m.points[v] + Vec3(0, 0, 1));
  const ArapResult r = arapDeform(m, constrained, targets);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.pinnedVertices, base);
  for (int v = 0; v < base; ++v) {
    EXPECT_LE((r.positions[v] - (m.points[v] + Vec3(0, 0, 1))).norm(), 1e-9);  // translated as one
    EXPECT_EQ(r.positions[v + base], m.points[v + base]);
  }
  EXPECT_FALSE(arapDeform(m, {0, 99999}, {Vec3::Zero(), Vec3::Zero()}).status.ok());
  EXPECT_FALSE(arapDeform(m, {0}, {Vec3(NAN, 0, 0)}).status.ok());
  EXPECT_FALSE(arapDeform(m, {0, 0}, {Vec3(0, 0, 0), Vec3(1, 0, 0)}).status.ok());
  EXPECT_FALSE(arapDeform(m, {0}, {}).status.ok());
}

TEST(DeformDemo, DefaultsPickTheFarthestAndTheLargestComponentsAndLabelsAreChecked) {
  // U: base and two arms, three components. Handle: the component whose centroid is farthest
  // from the whole's; anchor: the largest other one.
  const acd::TriMesh u = acd::shapes::uShape();
  HullMeshOptions ho;  // the exact complex: the surface on the handle then moves exactly
  ho.mesher = Mesher::Complex;
  ho.simplify = 0;
  ho.tau = 0.05;
  ho.threads = 1;
  ho.tetgen.radiusEdge = 2.0;
  ho.tetgen.maxVolume = 0.02;  // fine enough that the arms have tets away from the base
  const HullMeshResult mesh = meshHulls(u, ho);
  ASSERT_TRUE(mesh.status.ok()) << mesh.status.message;
  ASSERT_EQ(mesh.decomposition.components.size(), 3u);
  const TetMesh& m = mesh.mesh;
  std::map<int, double> volume;
  std::map<int, Vec3> moment;
  Vec3 all = Vec3::Zero();
  double total = 0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    Vec3 c = Vec3::Zero();
    for (int v : m.tets[t]) c += m.points[v] / 4.0;
    const double vol = tetVolume(m, t);
    volume[m.labels[t]] += vol, total += vol;
    moment.emplace(m.labels[t], Vec3::Zero()).first->second += vol * c;
    all += vol * c;
  }
  auto centroid = [&](int label) { return Vec3(moment[label] / volume[label]); };
  const DeformationResult r = deformSurface(m, u, {});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NE(r.handle, r.anchor);
  for (const auto& [label, vol] : volume) {
    EXPECT_LE((centroid(label) - all / total).norm(), (centroid(r.handle) - all / total).norm() + 1e-12) << label;
    if (label != r.handle) {
      EXPECT_LE(vol, volume[r.anchor] + 1e-12) << label;
    }
  }
  const acd::Box3 h = acd::boundingBox(mesh.decomposition.components[r.handle - 1].mesh);
  EXPECT_EQ(r.embedding.outside, 0);
  EXPECT_EQ(r.arap.invertedTets, 0);
  EXPECT_EQ(r.surfaceAfter.faces, u.faces);
  EXPECT_GT(r.surfaceOnHandle, 0);
  EXPECT_LE(r.surfaceHandleError, 1e-12);
  EXPECT_NEAR(r.translation.norm(), 0.2 * r.halfDiagonal, 1e-12);
  EXPECT_NEAR(r.translation.dot(centroid(r.handle) - centroid(r.anchor)), 0.0, 1e-9);  // across the handle-anchor direction
  // The surface vertices of the handle arm's far end moved with it.
  int moved = 0;
  for (std::size_t i = 0; i < u.vertices.size(); ++i)
    if (u.vertices[i].y() >= h.hi.y() - 1e-9 && u.vertices[i].x() >= h.lo.x() - 1e-9 && u.vertices[i].x() <= h.hi.x() + 1e-9) {
      EXPECT_LE((r.surfaceAfter.vertices[i] - (u.vertices[i] + r.translation)).norm(), 1e-9);
      ++moved;
    }
  EXPECT_GT(moved, 0);
  // Bad choices.
  DeformationOptions o;
  o.handle = 7;
  EXPECT_NE(deformSurface(mesh.mesh, u, o).status.message.find("no component 7"), std::string::npos);
  o.handle = o.anchor = 2;
  EXPECT_NE(deformSurface(mesh.mesh, u, o).status.message.find("same component"), std::string::npos);
  o = {};
  o.rotate = o.translate = true;
  EXPECT_FALSE(deformSurface(mesh.mesh, u, o).status.ok());
}

TEST(DeformDemo, OneComponentIsSplitAlongItsLongestSide) {
  // A convex bar is one component: its last fifth along x is moved, its first fifth held.
  const acd::TriMesh bar = acd::shapes::voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}});  // 5 x 1 x 1
  HullMeshOptions ho;  // the exact complex: the bar's own faces
  ho.mesher = Mesher::Complex;
  ho.simplify = 0;
  ho.threads = 1;
  ho.tetgen.radiusEdge = 2.0;
  ho.tetgen.maxVolume = 0.05;
  const HullMeshResult mesh = meshHulls(bar, ho);
  ASSERT_TRUE(mesh.status.ok()) << mesh.status.message;
  const DeformationResult r = deformSurface(mesh.mesh, bar, {});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.handle, 0);
  int expectedHandle = 0, expectedAnchor = 0;
  for (const Vec3& p : mesh.mesh.points) expectedHandle += p.x() >= 4.0 ? 1 : 0, expectedAnchor += p.x() <= 1.0 ? 1 : 0;
  EXPECT_EQ(r.handleVertices, expectedHandle);
  EXPECT_EQ(r.anchorVertices, expectedAnchor);
  int ends = 0;
  for (std::size_t i = 0; i < bar.vertices.size(); ++i) {
    if (bar.vertices[i].x() != 0 && bar.vertices[i].x() != 5) continue;  // the ends are corners of the mesh
    const Vec3 expected = bar.vertices[i].x() == 5 ? Vec3(bar.vertices[i] + r.translation) : bar.vertices[i];
    EXPECT_LE((r.surfaceAfter.vertices[i] - expected).norm(), 1e-12) << bar.vertices[i].transpose();
    ++ends;
  }
  EXPECT_EQ(ends, 8);
  EXPECT_EQ(r.arap.invertedTets, 0);
  EXPECT_EQ(r.selfIntersectionsBefore, 0);
  EXPECT_EQ(r.selfIntersectionsAfter, 0);
  // Pushed far enough sideways, the far end runs through the held one: a bar bent into a U.
  DeformationOptions fold;
  fold.translate = true;
  fold.move = Vec3(-4.5, 0, 0.5);
  const DeformationResult folded = deformSurface(mesh.mesh, bar, fold);
  ASSERT_TRUE(folded.status.ok()) << folded.status.message;
  EXPECT_GT(folded.selfIntersectionsAfter, 0);
  DeformationOptions o;
  o.handle = 1;
  EXPECT_NE(deformSurface(mesh.mesh, bar, o).status.message.find("one component"), std::string::npos);
}

TEST(DeformCli, ElephantWritesFourFilesThatParseBack) {
  acdtest::TempDir dir("tetmesh_deform_cli");
  const std::string model = std::string(ACD_DATA_DIR) + "/meshes/elephant.off";
  const acd::ReadResult input = acd::readMesh(model);
  ASSERT_TRUE(input.status.ok());
  auto r = acdtest::runTool(TETMESH_CLI,
                            acdtest::quote(model) + " --tau 0.2 --threads 1 --deform " + acdtest::quote(dir / "out") +
                                " --deform-angle 20 --json " + acdtest::quote(dir / "report.json"),
                            dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("embedding"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ARAP"), std::string::npos) << r.out;
  for (const char* name : {"surface_before.off", "surface_after.off"}) {
    const acd::ReadResult back = acd::readMesh(dir / (std::string("out/") + name));
    ASSERT_TRUE(back.status.ok()) << name << ": " << back.status.message;
    EXPECT_EQ(back.mesh.vertices.size(), input.mesh.vertices.size()) << name;
    EXPECT_EQ(back.mesh.faces, input.mesh.faces) << name;
  }
  const acd::ReadResult after = acd::readMesh(dir / "out/surface_after.off");
  double moved = 0;
  for (std::size_t i = 0; i < input.mesh.vertices.size(); ++i) moved = std::max(moved, (after.mesh.vertices[i] - input.mesh.vertices[i]).norm());
  EXPECT_GT(moved, 0.01);  // something moved
  for (const char* name : {"tets_before.vtk", "tets_after.vtk"}) {
    std::ifstream in(dir / (std::string("out/") + name));
    std::string line, word;
    int points = -1, cells = -1;
    while (in >> word) {
      if (word == "POINTS") in >> points;
      if (word == "CELLS") in >> cells;
    }
    EXPECT_GT(points, 0) << name;
    EXPECT_GT(cells, 0) << name;
  }
  // The parts: rest, handle and anchor, which together are the whole surface.
  const acd::ObjObjects parts = acd::readObjObjects(dir / "out/parts_after.obj");
  ASSERT_TRUE(parts.status.ok()) << parts.status.message;
  EXPECT_EQ(parts.names, (std::vector<std::string>{"rest", "handle", "anchor"}));
  std::size_t faces = 0;
  for (const acd::TriMesh& p : parts.objects) faces += p.faces.size();
  EXPECT_EQ(faces, input.mesh.faces.size());
  const std::string json = acdtest::slurp(dir / "report.json");
  EXPECT_NE(json.find("\"deformation\""), std::string::npos);
  EXPECT_NE(json.find("\"inverted_tets\""), std::string::npos);
}

TEST(DeformCli, BadDeformOptionsExitThreeAndUnwritableDirFive) {
  acdtest::TempDir dir("tetmesh_deform_bad");
  ASSERT_TRUE(acd::writeMesh(dir / "u.off", acd::shapes::uShape()).ok());
  const std::string base = acdtest::quote(dir / "u.off") + " --tau 0.05 --deform " + acdtest::quote(dir / "out");
  auto r = acdtest::runTool(TETMESH_CLI, base + " --deform-handle 9", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("no component 9"), std::string::npos) << r.err;
  r = acdtest::runTool(TETMESH_CLI, base + " --deform-handle 1 --deform-anchor 1", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("same component"), std::string::npos) << r.err;
  r = acdtest::runTool(TETMESH_CLI, base + " --deform-move 1,0,0 --deform-angle 30", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  r = acdtest::runTool(TETMESH_CLI, base + " --deform-move 1,nan,0", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  r = acdtest::runTool(TETMESH_CLI, base + " --deform-iterations -1", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  r = acdtest::runTool(TETMESH_CLI, base + " --deform-min-weight -0.5", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  r = acdtest::runTool(TETMESH_CLI, acdtest::quote(dir / "u.off") + " --deform-handle 1", dir);
  EXPECT_NE(r.code, 0) << "--deform-handle without --deform";
  r = acdtest::runTool(TETMESH_CLI, acdtest::quote(dir / "u.off") + " --tau 0.05 --deform /dev/null/out", dir);
  EXPECT_EQ(r.code, 5) << r.err;
  EXPECT_NE(r.err.find("/dev/null/out"), std::string::npos) << r.err;
  // And a good run on the U: the default handle and anchor, counts kept.
  r = acdtest::runTool(TETMESH_CLI, base, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const acd::ReadResult after = acd::readMesh(dir / "out/surface_after.off");
  ASSERT_TRUE(after.status.ok()) << after.status.message;
  EXPECT_EQ(after.mesh.faces, acd::shapes::uShape().faces);
}
