// acd: approximate convex decomposition (Lien & Amato 2007). This header is the stable API:
// include it and use what it declares.
//
//   const acd::ReadResult in = acd::readMesh("model.off");   // io.hpp
//   acd::DecomposeOptions o;
//   o.tau = 0.05;
//   const acd::Decomposition d = acd::decompose(in.mesh, o);   // decompose.hpp
//   for (const acd::Component& c : d.components) use(c.hull);
//
// What each header offers:
//   mesh, status, io, scene_io, shapes     triangle meshes, results, files, test solids
//   diagnosis, repair                      what is wrong with a mesh, and the safe repairs
//   decompose, robust                      solid decomposition (any mesh: repairs, shells, wrap)
//   surface_decompose                      surface decomposition (open meshes, any genus)
//   post_passes, mass_properties           hull budget, vertex cap, tau as a length, mass
//   exact_decomposition, surface_exact     exact baselines (link acd::baselines)
//   evaluate, inside, hull, normalize      measures of a decomposition, point-in-solid, hulls
//   report, simulator_export               report.json, URDF / MJCF / SDF / glTF output
//
// The steps of the method have headers under acd/algo/ (concavity, bridges and pockets, handle
// cuts, knots, global cuts, plane cuts, merges...): internal but exposed, for tests, benchmarks
// and experiments. They may change between minor versions; docs/ARCHITECTURE.md maps them.
#pragma once

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/hull.hpp>
#include <acd/inside.hpp>
#include <acd/io.hpp>
#include <acd/mass_properties.hpp>
#include <acd/mesh.hpp>
#include <acd/normalize.hpp>
#include <acd/plane.hpp>
#include <acd/post_passes.hpp>
#include <acd/repair.hpp>
#include <acd/report.hpp>
#include <acd/robust.hpp>
#include <acd/scene_io.hpp>
#include <acd/shapes.hpp>
#include <acd/simulator_export.hpp>
#include <acd/status.hpp>
#include <acd/surface_decompose.hpp>
#include <acd/surface_exact.hpp>
#include <acd/version.hpp>
