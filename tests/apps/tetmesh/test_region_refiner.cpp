// The refinement of hull regions (the default mesher): shapes with known answers, and the
// issue's targets on a corpus model against TetGen on the model itself.
#include "hull_mesher.hpp"
#include "region_features.hpp"
#include "region_labels.hpp"
#include "region_refiner.hpp"
#include "sliver_repair.hpp"
#include "tet_checks.hpp"

#include <acd/algo/shapes.hpp>
#include <acd/io.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace tetmesh;

namespace {

RefineOptions coarse(double facetDistance) {
  RefineOptions o;
  o.facetDistance = facetDistance;
  o.closedGap = facetDistance;
  o.sliverMove = 0.5 * facetDistance;
  return o;
}

double smallestAngle(const TetMesh& m) {
  double smallest = 180.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) smallest = std::min(smallest, tmtest::smallestDihedralDegrees(m, t));
  return smallest;
}

double volume(const TetMesh& m, int label = -1) {
  double v = 0.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t)
    if (label < 0 || m.labels[t] == label) v += tetVolume(m, t);
  return v;
}

/// Each face in one tet (boundary) or two; faces between labels are the interface.
struct Faces {
  double interfaceArea = 0.0;
  int interface = 0, boundary = 0;
  bool conforming = true;
};

Faces classify(const TetMesh& m, const std::function<void(const std::array<int, 3>&)>& onInterface = {}) {
  Faces f;
  for (const auto& [face, tets] : tmtest::tetFaces(m)) {
    if (tets.size() > 2) f.conforming = false;
    if (tets.size() == 1) ++f.boundary;
    if (tets.size() == 2 && m.labels[tets[0]] != m.labels[tets[1]]) {
      ++f.interface;
      f.interfaceArea += tmtest::triangleArea(m, face);
      if (onInterface) onInterface(face);
    }
  }
  return f;
}

}  // namespace

TEST(RegionRefiner, TwoBoxesFaceToFaceShareOneFlatInterfaceWithoutSlivers) {
  const std::vector<acd::TriMesh> boxes = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                           acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1))};
  const RefineResult r = refineRegions(boxes, coarse(0.02));
  ASSERT_TRUE(r.ok) << r.error;
  const TetMesh& m = r.mesh;
  EXPECT_EQ(std::set<int>(m.labels.begin(), m.labels.end()), (std::set<int>{1, 2}));
  for (std::size_t t = 0; t < m.tets.size(); ++t) ASSERT_GT(tetVolume(m, static_cast<int>(t)), 0.0);
  // One interface, on the contact plane away from its rim (where the rounded edges meet it,
  // within two facet distances), within the refinement's bisection error.
  double farthestInside = 0.0, farthest = 0.0;
  const Faces f = classify(m, [&](const std::array<int, 3>& face) {
    for (int v : face) {
      const Vec3& p = m.points[v];
      const double off = std::abs(p.x() - 1.0);
      farthest = std::max(farthest, off);
      if (std::min({p.y(), 1 - p.y(), p.z(), 1 - p.z()}) > 0.04) farthestInside = std::max(farthestInside, off);
    }
  });
  EXPECT_TRUE(f.conforming);
  EXPECT_LE(farthestInside, 1e-5);
  EXPECT_LE(farthest, 0.04);
  EXPECT_GT(f.interfaceArea, 0.9);
  EXPECT_LE(f.interfaceArea, 1.02);
  // Each box fills its own side (edges rounded within the facet distance).
  EXPECT_NEAR(volume(m, 1), 1.0, 0.05);
  EXPECT_NEAR(volume(m, 2), 1.0, 0.05);
  EXPECT_GE(smallestAngle(m), kSliverDegrees);
  // The face markers say the same as the tets.
  int markedInterface = 0;
  for (int k : m.faceMarkers) markedInterface += k == kInterfaceFacet ? 1 : 0;
  EXPECT_EQ(markedInterface, f.interface);
  EXPECT_EQ(static_cast<int>(m.faces.size()), f.interface + f.boundary);
}

TEST(RegionRefiner, AnLWithAHairlineGapIsOnePieceAcrossIt) {
  // A slab [0,2]x[0,1]x[0,1] and a cube on its left half, 1e-6 above it.
  const std::vector<acd::TriMesh> l = {acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1)),
                                       acd::shapes::box(Vec3(0, 0, 1 + 1e-6), Vec3(1, 1, 2))};
  const RefineResult r = refineRegions(l, coarse(0.02));
  ASSERT_TRUE(r.ok) << r.error;
  const TetMesh& m = r.mesh;
  // No boundary face lies in the gap's footprint: the cube sits on the slab through interface faces.
  int inGap = 0;
  for (const auto& [face, tets] : tmtest::tetFaces(m)) {
    if (tets.size() != 1) continue;
    Vec3 c = Vec3::Zero();
    for (int v : face) c += m.points[v] / 3.0;
    if (std::abs(c.z() - 1.0) < 1e-3 && c.x() > 0.05 && c.x() < 0.95 && c.y() > 0.05 && c.y() < 0.95) ++inGap;
  }
  EXPECT_EQ(inGap, 0);
  const Faces f = classify(m);
  EXPECT_TRUE(f.conforming);
  EXPECT_GT(f.interfaceArea, 0.9);
  EXPECT_LE(f.interfaceArea, 1.02);
  EXPECT_GE(smallestAngle(m), kSliverDegrees);
  EXPECT_NEAR(volume(m), 3.0, 0.15);
}

TEST(RegionRefiner, TheSameInputGivesTheSameMesh) {
  // Bit for bit, also in one process, where a second call reuses the first's memory (CGAL's
  // perturbation step did not repeat itself there; it is not used).
  const std::vector<acd::TriMesh> boxes = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                           acd::shapes::box(Vec3(1, 0.2, 0), Vec3(1.5, 0.8, 3))};
  RefineOptions quality = coarse(0.03);
  quality.radiusEdge = 1.5;
  for (const RefineOptions& o : {coarse(0.03), quality}) {
    const RefineResult a = refineRegions(boxes, o);
    for (int run = 0; run < 3; ++run) {
      const RefineResult b = refineRegions(boxes, o);
      ASSERT_TRUE(a.ok && b.ok);
      EXPECT_EQ(a.mesh.points, b.mesh.points);
      EXPECT_EQ(a.mesh.tets, b.mesh.tets);
      EXPECT_EQ(a.mesh.labels, b.mesh.labels);
      EXPECT_EQ(a.mesh.faces, b.mesh.faces);
    }
  }
}

TEST(RegionRefiner, NothingToMeshIsAMessage) {
  EXPECT_FALSE(refineRegions({}, coarse(0.1)).ok);
  EXPECT_FALSE(refineRegions({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))}, coarse(0.0)).ok);
}

TEST(SliverRepair, AFlatTetIsLiftedWithinTheAllowedMove) {
  // A tet whose apex lies 0.01 above its base: a sliver the repair can lift.
  TetMesh m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 0.01)};
  m.tets = {{0, 1, 2, 3}};
  m.labels = {1};
  ASSERT_LT(tmtest::smallestDihedralDegrees(m, 0), 5.0);
  TetMesh fixedInPlace = m;
  const SliverRepair none = repairSlivers(fixedInPlace, 5.0, 0.0);
  EXPECT_EQ(none.moves, 0);
  EXPECT_EQ(fixedInPlace.points, m.points);
  const SliverRepair r = repairSlivers(m, 5.0, 0.5);
  EXPECT_EQ(r.before, 1);
  EXPECT_EQ(r.after, 0);
  EXPECT_GE(tmtest::smallestDihedralDegrees(m, 0), 5.0);
  for (std::size_t v = 0; v < m.points.size(); ++v) EXPECT_LE((m.points[v] - fixedInPlace.points[v]).norm(), 0.5 + 1e-12);
  EXPECT_GT(tetVolume(m, 0), 0.0);
}

TEST(RegionRefiner, ClippedComponentsHoldTheModelsVolume) {
  // A torus: its components' hulls stand off it; clipped to it, the mesh holds its volume.
  const acd::TriMesh torus = acd::shapes::torus(2.0, 0.6, 48, 16);
  HullMeshOptions o;
  o.tau = 0.1;
  o.threads = 1;
  o.coarsen = false;  // the refinement's own surface, within the facet distance
  const HullMeshResult hulls = meshHulls(torus, o);
  o.clip = true;
  const HullMeshResult clipped = meshHulls(torus, o);
  ASSERT_TRUE(hulls.status.ok() && clipped.status.ok()) << hulls.status.message << clipped.status.message;
  // An inscribed surface within the facet distance d of the model's loses at most area x d.
  const double model = acd::signedVolume(torus);
  double area = 0.0;
  for (const acd::Face& f : torus.faces)
    area += 0.5 * (torus.vertices[f[1]] - torus.vertices[f[0]]).cross(torus.vertices[f[2]] - torus.vertices[f[0]]).norm();
  const double d = clipped.refineOptions.facetDistance;
  EXPECT_LE(volume(clipped.mesh), model * (1 + 1e-9));
  EXPECT_GE(volume(clipped.mesh), model - area * d);
  EXPECT_GT(volume(hulls.mesh), model);
  std::printf("[ torus    ] model %.4f, clipped %.4f (bound %.4f), hulls %.4f\n", model, volume(clipped.mesh), model - area * d,
              volume(hulls.mesh));
  EXPECT_EQ(clipped.quality.slivers, 0);
  EXPECT_GE(smallestAngle(clipped.mesh), kSliverDegrees);
}

TEST(RegionRefiner, ElephantCoarseAndQualityAgainstTetGenOnTheModel) {
  // The targets of docs/TETMESH.md on one corpus model: coarse, no tet below 5 degrees and at most
  // half the tets of TetGen's unrefined mesh of the model; at radius-edge 1.5, no smaller angle
  // than TetGen's refined mesh of the model and no more tets. Every component's region has tets;
  // before the coarse mesh's collapses (and in the quality mode) none lost more than half its
  // volume where that loss is more than 1 % of the regions' (the rounding of a small region's
  // edges alone takes a large share of it; the refinement meshes a region again only for a loss
  // that matters).
  const acd::ReadResult read = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  for (double quality : {0.0, 1.5}) {
    HullMeshOptions o;
    o.tau = 0.2;
    o.threads = 1;
    o.tetgen.radiusEdge = quality;
    const HullMeshResult r = meshHulls(read.mesh, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    o.coarsen = false;
    o.surfaceDistance = r.refineOptions.facetDistance / (o.tau / r.decomposition.normalization.scale);  // the same start
    const HullMeshResult refined = quality == 0 ? meshHulls(read.mesh, o) : r;
    ASSERT_TRUE(refined.status.ok()) << refined.status.message;
    EXPECT_EQ(r.coarsened, quality == 0);
    TetGenOptions direct;
    direct.radiusEdge = quality;
    const DirectMeshResult model = meshModelDirectly(read.mesh, direct);
    ASSERT_TRUE(model.status.ok()) << model.status.message;
    const double ours = smallestAngle(r.mesh), theirs = smallestAngle(model.tetgen.mesh);
    double all = 0.0;
    for (const acd::TriMesh& region : r.regions) all += acd::signedVolume(region);
    for (std::size_t i = 0; i < r.regions.size(); ++i) {
      const double region = acd::signedVolume(r.regions[i]), meshed = volume(refined.mesh, static_cast<int>(i) + 1);
      EXPECT_GT(volume(r.mesh, static_cast<int>(i) + 1), 0.0) << "component " << i + 1;
      EXPECT_TRUE(meshed >= 0.5 * region || region - meshed <= 0.01 * all) << "component " << i + 1;
    }
    if (quality == 0) {
      EXPECT_GE(ours, kSliverDegrees);
      EXPECT_LE(2 * r.mesh.tets.size(), model.tetgen.mesh.tets.size());
    } else {
      EXPECT_GE(ours, theirs);
      EXPECT_LE(r.mesh.tets.size(), model.tetgen.mesh.tets.size());
      EXPECT_LE(r.quality.maxRadiusEdge, 2.0);
    }
    std::printf("[ elephant ] quality %g: %zu tets (TetGen on the model %zu), smallest angle %.2f (%.2f)\n", quality,
                r.mesh.tets.size(), model.tetgen.mesh.tets.size(), ours, theirs);
  }
}

TEST(RegionRefiner, AWallThinnerThanTheFacetDistanceIsMeshed) {
  // Two walls 0.02 thick under a facet distance of 0.03: missed at first, meshed again with a
  // smaller facet distance until each holds at least half its volume.
  const std::vector<acd::TriMesh> walls = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 0.02)),
                                           acd::shapes::box(Vec3(0, 0, 0.02), Vec3(0.02, 1, 1))};
  const RefineResult r = refineRegions(walls, coarse(0.03));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.regionsRefined, 0);
  const double each = 0.02;  // 1 x 1 x 0.02 and 0.02 x 1 x 0.98 (less its rounded edges)
  EXPECT_GT(volume(r.mesh, 1), 0.5 * each);
  EXPECT_GT(volume(r.mesh, 2), 0.5 * 0.98 * each);
  EXPECT_LE(volume(r.mesh), each + 0.98 * each + 1e-9);
  EXPECT_GE(smallestAngle(r.mesh), kSliverDegrees);
}

TEST(RegionRefiner, SharpEdgesKeepABoxExact) {
  // Kept edges (faces turning by 90 degrees) are protected: the box's volume is exact and its
  // corners are mesh vertices; rounded (the default), it loses a little at every edge.
  const std::vector<acd::TriMesh> box = {acd::shapes::box(Vec3(0, 0, 0), Vec3(3, 1.5, 4))};
  RefineOptions sharp = coarse(0.1);
  sharp.featureAngle = 30;
  sharp.edgeSize = 0.5;
  const RefineResult kept = refineRegions(box, sharp), rounded = refineRegions(box, coarse(0.1));
  ASSERT_TRUE(kept.ok && rounded.ok) << kept.error << rounded.error;
  EXPECT_EQ(kept.features, 12);
  EXPECT_NEAR(volume(kept.mesh), 18.0, 1e-5 * 18);  // the refinement's bisection error, relative 1e-6
  EXPECT_LT(volume(rounded.mesh), 18.0 - 1e-3);
  for (const Vec3& corner : box[0].vertices)
    EXPECT_NE(std::find(kept.mesh.points.begin(), kept.mesh.points.end(), corner), kept.mesh.points.end()) << corner.transpose();
  EXPECT_GE(smallestAngle(kept.mesh), kSliverDegrees);
}

TEST(RegionFeatures, NeighboursShareTheirRimsAndNearMissesAreDropped) {
  // Two boxes face to face: their 24 edges, less the 4 they share on the contact plane counted
  // once (the rim of the contact is an edge of both), and the contact's interior has none.
  const std::vector<acd::TriMesh> boxes = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                           acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1))};
  const RegionLabels labels(boxes, 0.0);
  const RegionFeatures f = regionFeatures(boxes, labels, 30.0, 0.01);
  EXPECT_EQ(f.candidates, 24);
  EXPECT_EQ(f.segments.size(), 20u);
  EXPECT_EQ(f.dropped, 0);
  // Chained: the outline loops and the four edges along x, each from x = 0 to x = 2 in two pieces.
  const auto lines = chainSegments(f.segments);
  std::size_t points = 0;
  for (const auto& line : lines) points += line.size() - 1;
  EXPECT_EQ(points, f.segments.size());
  // A box 0.005 beside another: the four edges of its near face run 0.005 from the other's,
  // closer than the clearance 0.01: one of each pair goes.
  const std::vector<acd::TriMesh> near = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                          acd::shapes::box(Vec3(1.005, 0, 0), Vec3(2, 1, 1))};
  const RegionFeatures g = regionFeatures(near, RegionLabels(near, 0.0), 30.0, 0.01);
  EXPECT_GE(g.dropped, 4);
  for (std::size_t s = 0; s < g.segments.size(); ++s)
    for (std::size_t t = s + 1; t < g.segments.size(); ++t) {
      const auto &a = g.segments[s], &b = g.segments[t];
      const bool meet = a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
      if (meet) continue;
      // Far apart: the midpoints at least (a weak, independent check of the clearance).
      EXPECT_GT((0.5 * (a[0] + a[1]) - 0.5 * (b[0] + b[1])).norm(), 0.01);
    }
}

TEST(AutoMesher, BoxyPartsGetTheExactComplexCurvedOnesTheRefinement) {
  // An L of boxes: every hull has 8 corners and the complex's mesh has no sliver, so it is kept
  // (exact volume, a handful of tets). A torus: hulls of many corners, the refinement.
  HullMeshOptions o;
  o.tau = 0.05;
  o.threads = 1;
  const HullMeshResult l = meshHulls(acd::shapes::lShape(), o);
  ASSERT_TRUE(l.status.ok()) << l.status.message;
  EXPECT_EQ(l.used, Mesher::Complex);
  EXPECT_EQ(l.complexSlivers, 0);
  EXPECT_NEAR(volume(l.mesh), 3.0, 1e-12);
  EXPECT_LT(l.mesh.tets.size(), 50u);
  EXPECT_GE(smallestAngle(l.mesh), kSliverDegrees);
  o.tau = 0.1;
  const HullMeshResult torus = meshHulls(acd::shapes::torus(2.0, 0.6, 48, 16), o);
  ASSERT_TRUE(torus.status.ok()) << torus.status.message;
  EXPECT_EQ(torus.used, Mesher::Refine);
  EXPECT_GE(smallestAngle(torus.mesh), kSliverDegrees);
  // Asked to clip, the refinement runs whatever the hulls.
  o.clip = true;
  o.tau = 0.05;
  EXPECT_EQ(meshHulls(acd::shapes::lShape(), o).used, Mesher::Refine);
}
