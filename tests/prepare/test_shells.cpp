// Shells (libacd/src/prepare/shells.cpp, acd/algo/shells.hpp): nesting depth finds the cavities,
// and preparing a model drops them and unites overlapping shells (or keeps them apart when told).
#include <acd/algo/shells.hpp>
#include <acd/decompose.hpp>
#include <acd/robust.hpp>

#include <gtest/gtest.h>

#include "bad_meshes.hpp"
#include "helpers.hpp"

using namespace acd;

namespace {

TriMesh caseMesh(const std::string& name) { return badmeshes::byName(name); }

DecomposeOptions atTau(double tau) {
  DecomposeOptions o;
  o.tau = tau;
  return o;
}

}  // namespace

// ------------------------------------------------------------------ shells
TEST(Shells, CavitiesAreFoundByNestingDepth) {
  const TriMesh outer = shapes::box(Vec3(0, 0, 0), Vec3(5, 5, 5));
  const TriMesh cavity = shapes::box(Vec3(1, 1, 1), Vec3(4, 4, 4));
  const TriMesh inner = shapes::box(Vec3(2, 2, 2), Vec3(3, 3, 3));
  const TriMesh apart = shapes::box(Vec3(7, 0, 0), Vec3(8, 1, 1));
  const TriMesh crossing = shapes::box(Vec3(4.5, 4.5, 4.5), Vec3(6, 6, 6));  // through the outer wall only
  const ShellNesting n = classifyShells({outer, cavity, inner, apart, crossing});
  EXPECT_EQ(n.depth, std::vector<int>({0, 1, 2, 0, 0}));
  EXPECT_EQ(n.cavities, 1);
  EXPECT_EQ(n.overlaps, std::vector<char>({1, 0, 0, 0, 1}));
}

TEST(Shells, PrepareDropsCavitiesAndKeepsOverlapsApart) {
  for (const char* name : {"nested_cavity", "nested_cavity_outward"}) {
    const PreparedModel p = prepareModel(caseMesh(name), atTau(0.1));
    ASSERT_TRUE(p.status.ok());
    EXPECT_EQ(p.cavitiesDropped, 1) << name;
    ASSERT_EQ(p.shells.size(), 1u) << name;
    EXPECT_NEAR(signedVolume(p.shells[0]), 27.0, 1e-12);
  }
  // Overlapping shells become their union (acd/algo/shell_union.hpp, the default), else stay apart.
  DecomposeOptions unite = atTau(0.1);
  unite.uniteShells = true;
  const PreparedModel loose = prepareModel(caseMesh("solid_in_cavity"), unite);
  EXPECT_EQ(loose.cavitiesDropped, 1);
  // With the cavity gone the solid inside it lies in the outer shell's solid: the union absorbs it.
  EXPECT_EQ(loose.shells.size(), 1u);
  DecomposeOptions apart = atTau(0.1);
  apart.uniteShells = false;
  EXPECT_EQ(prepareModel(caseMesh("solid_in_cavity"), apart).shells.size(), 2u);  // apart: both
  const PreparedModel united = prepareModel(caseMesh("shells_overlapping"), unite);
  EXPECT_EQ(united.overlappingShells, 0);
  EXPECT_EQ(united.shells.size(), 1u);
  const PreparedModel overlap = prepareModel(caseMesh("shells_overlapping"), apart);
  EXPECT_EQ(overlap.overlappingShells, 2);
  EXPECT_EQ(overlap.shells.size(), 2u);
}

