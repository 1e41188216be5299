// With `invariant`, a decomposition depends on the shape only: rigid motions (random, a 1e-9
// nudge, an exact quarter turn) and a shuffled face order give the same parts with the same volumes. And tau is a promise
// about what users measure: no hull sticks out of the model by more than tau, measured here with
// the tests' own distance code.
#include <acd/decompose.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include "helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <random>

namespace {

using acd::Decomposition;
using acd::DecomposeOptions;
using acd::TriMesh;
using acd::Vec3;
using acdtest::corpus;
using acdtest::moved;

TriMesh withShuffledFaces(const TriMesh& m, std::uint64_t seed) {
  TriMesh out = m;
  std::mt19937_64 rng(seed);
  std::shuffle(out.faces.begin(), out.faces.end(), rng);
  for (acd::Face& f : out.faces) std::rotate(f.begin(), f.begin() + static_cast<int>(rng() % 3), f.end());
  return out;
}

/// Component volumes (normalised units), largest first: what must match between poses.
std::vector<double> volumes(const Decomposition& d) {
  std::vector<double> v;
  for (const acd::Component& c : d.components) v.push_back(c.volume);
  std::sort(v.rbegin(), v.rend());
  return v;
}

/// A generated shape with no symmetry: an L of cells with a tower, a stub and a bent revolved arm.
TriMesh asymmetricShape() {
  return acd::shapes::voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 0, 1}, {0, 0, 2},
                              {1, 0, 2}, {2, 0, 2}, {0, 2, 1}});
}

void expectInvariant(const TriMesh& mesh, double tau, int motions) {
  DecomposeOptions o;
  o.tau = tau;
  o.invariant = true;
  const Decomposition reference = acd::decompose(mesh, o);
  ASSERT_TRUE(reference.status.ok()) << reference.status.message;
  const std::vector<double> expected = volumes(reference);
  const double size = 1.0 / reference.normalization.scale;

  std::vector<std::pair<std::string, TriMesh>> poses;
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> g;
  for (int k = 0; k < motions; ++k) {
    const double w = g(rng), x = g(rng), y = g(rng), z = g(rng);  // drawn in this order
    const Eigen::Matrix3d r = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
    poses.emplace_back("random motion " + std::to_string(k), moved(mesh, r, 3.0 * size * acdtest::drawPoint([&] { return g(rng); })));
  }
  poses.emplace_back("1e-9 translation", moved(mesh, Eigen::Matrix3d::Identity(), Vec3(1e-9, -1e-9, 1e-9) * size));
  poses.emplace_back("1e-12 translation", moved(mesh, Eigen::Matrix3d::Identity(), Vec3(1e-12, 0, 0) * size));
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  poses.emplace_back("quarter turn", moved(mesh, quarter, Vec3::Zero()));
  poses.emplace_back("shuffled faces", withShuffledFaces(mesh, 5));

  for (const auto& [name, posed] : poses) {
    SCOPED_TRACE(name);
    const Decomposition d = acd::decompose(posed, o);
    ASSERT_TRUE(d.status.ok()) << d.status.message;
    const std::vector<double> got = volumes(d);
    ASSERT_EQ(got.size(), expected.size()) << "part count";
    for (std::size_t i = 0; i < got.size(); ++i)
      EXPECT_NEAR(got[i], expected[i], 1e-6 * expected[i]) << "component " << i << " by volume";
  }
}

TEST(DecomposeInvariance, GeneratedShape) { expectInvariant(asymmetricShape(), 0.05, 5); }

// (cow passes through itself and is repaired around its crossings, in the canonical frame too.)
TEST(DecomposeInvariance, CorpusModels) {
  for (const auto& [model, tau] : std::vector<std::pair<std::string, double>>{{"eight", 0.05}, {"elephant", 0.1}, {"cow", 0.1}}) {
    SCOPED_TRACE(model);
    const acd::ReadResult r = acd::readMesh(corpus(model));
    if (!r.status.ok()) GTEST_SKIP() << corpus(model) << " not present (scripts/fetch_corpus.sh)";
    expectInvariant(r.mesh, tau, 3);
  }
}

// Armadillo (52k faces) goes through the working mesh by default: it is made in the canonical
// frame and order, so the parts do not move with the input either.
TEST(DecomposeInvariance, ThroughTheWorkingMesh) {
  const acd::ReadResult r = acd::readMesh(corpus("armadillo"));
  if (!r.status.ok()) GTEST_SKIP() << corpus("armadillo") << " not present (scripts/fetch_corpus.sh)";
  ASSERT_GE(r.mesh.faces.size(), static_cast<std::size_t>(DecomposeOptions{}.workingFromFaces));
  expectInvariant(r.mesh, 0.05, 2);
}

/// Largest distance from a sample of the hulls' surfaces to the model, for samples outside the
/// model (inside it a hull does not stick out), in normalised units.
double hullsStickOut(const TriMesh& model, const Decomposition& d, int samples) {
  const acd::Normalization& n = d.normalization;
  const TriMesh m = acd::applyNormalization(model, n);
  const acdtest::MeshIndex index(m);
  std::vector<TriMesh> hulls;
  double total = 0;
  for (const acd::Component& c : d.components) {
    hulls.push_back(acd::applyNormalization(c.hull, n));
    total += acd::surfaceArea(hulls.back());
  }
  std::mt19937_64 rng(99);
  double worst = 0;
  for (const TriMesh& h : hulls) {
    const int count = std::max(50, static_cast<int>(samples * acd::surfaceArea(h) / total));
    for (const Vec3& p : acdtest::sampleSurface(h, count, rng))
      if (index.winding(p) == 0) worst = std::max(worst, index.distance(p));
  }
  return worst;
}

TEST(DecomposeTauKept, HullsStayWithinTauOfTheModel) {
  const double tau = 0.05;
  for (const char* model : {"elephant", "eight", "dino", "camel", "cow"}) {
    SCOPED_TRACE(model);
    const acd::ReadResult r = acd::readMesh(corpus(model));
    if (!r.status.ok()) GTEST_SKIP() << corpus(model) << " not present (scripts/fetch_corpus.sh)";
    DecomposeOptions o = acd::recommendedOptions();  // as the acd command decomposes
    o.tau = tau;
    const Decomposition d = acd::decompose(r.mesh, o);
    ASSERT_TRUE(d.status.ok()) << d.status.message;
    for (const acd::Component& c : d.components) EXPECT_FALSE(c.unresolved) << c.note;
    const double out = hullsStickOut(r.mesh, d, 40000);
    ::testing::Test::RecordProperty(std::string(model) + "_stick_out", std::to_string(out));
    // (The cow passes through itself: it is repaired around its crossings and held to tau, as the
    // others. Through its wrap, before, it reached 1.03 tau.)
    EXPECT_LE(out, tau) << "a hull sticks out of " << model << " by " << out;
  }
}

/// The share of the union of model and hulls that both cover (IoU), from `samples` points drawn
/// uniformly in the model's box grown by 5 % on each side: inside the model or a hull by the
/// tests' own winding number (the library's measure is not used).
double intersectionOverUnion(const TriMesh& model, const Decomposition& d, int samples) {
  const acdtest::MeshIndex index(model);
  std::vector<std::unique_ptr<acdtest::MeshIndex>> hulls;
  for (const acd::Component& c : d.components) hulls.push_back(std::make_unique<acdtest::MeshIndex>(c.hull));
  const Vec3 grow = 0.05 * (index.hi() - index.lo());
  const Vec3 lo = index.lo() - grow, hi = index.hi() + grow;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long both = 0, either = 0;
  for (int i = 0; i < samples; ++i) {
    const Vec3 p = lo + acdtest::drawPoint([&] { return unit(rng); }).cwiseProduct(hi - lo);
    const bool inModel = index.winding(p) != 0;
    const bool inHull = std::any_of(hulls.begin(), hulls.end(), [&](const auto& h) {
      return (p.array() >= h->lo().array()).all() && (p.array() <= h->hi().array()).all() && h->winding(p) != 0;
    });
    both += inModel && inHull;
    either += inModel || inHull;
  }
  return static_cast<double>(both) / static_cast<double>(either);
}

// The handle (a waisted block with a blind bore) at tau 0.015: no more parts than CoACD's 12 at its
// default setting, at an IoU above CoACD's 0.988 (docs/BENCHMARKS.md). Before the plane across the
// bore's floor competed, the first cut ran diagonally through the block and it took 19 parts.
TEST(DecomposeFewParts, TheHandleNeedsNoMorePartsThanCoACDAtItsFidelity) {
  const acd::ReadResult r = acd::readMesh(corpus("handle"));
  if (!r.status.ok()) GTEST_SKIP() << corpus("handle") << " not present (scripts/fetch_corpus.sh)";
  DecomposeOptions o = acd::recommendedOptions();  // as the acd command decomposes
  o.tau = 0.015;
  const Decomposition d = acd::decompose(r.mesh, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  for (const acd::Component& c : d.components) EXPECT_FALSE(c.unresolved) << c.note;
  EXPECT_LE(d.components.size(), 12u);
  EXPECT_GE(d.components.size(), 2u);  // its bore, 0.42 deep, is far above tau
  const double iou = intersectionOverUnion(r.mesh, d, 400000);
  ::testing::Test::RecordProperty("handle_iou", std::to_string(iou));
  EXPECT_GE(iou, 0.985);
  EXPECT_LE(hullsStickOut(r.mesh, d, 40000), o.tau);
}

}  // namespace
