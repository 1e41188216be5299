// acd: approximate convex decomposition (Lien & Amato 2007). This header is the stable API's
// core: include it and use what it declares (docs/API.md has a complete program).
//
//   const acd::ReadResult in = acd::readMesh("model.off");              // io.hpp
//   acd::DecomposeOptions o;                                            // decompose.hpp
//   o.tau = 0.05;
//   const acd::Decomposition d = acd::decomposeRepaired(in.mesh, o);    // robust.hpp: any mesh
//   for (const acd::Component& c : d.components) use(c.hull);
//
//   mesh, status        triangle meshes, and what every call returns on failure
//   io                  mesh files (OFF, OBJ, PLY, STL; scenes through scene_io.hpp)
//   decompose, robust   solid decomposition: of a clean closed solid, and of any mesh (repairs,
//                       shells, wrap)
//   surface_decompose   surface decomposition (open meshes, any genus)
//   evaluate            IoU, hull excess and surface distances of any set of hulls
//   version             ACD_VERSION
//
// Entry headers beside it: acd/baselines.hpp (exact decompositions; link acd::baselines),
// acd/export.hpp (report.json and simulator files). The other top-level headers are stable
// too (diagnosis, repair, post_passes, scene_io); acd/algo/ holds the steps of the method and
// the tools they share, exposed for tests, benchmarks and experiments, which may change between
// minor versions (docs/API.md lists them).
#pragma once

#include <acd/decompose.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/robust.hpp>
#include <acd/status.hpp>
#include <acd/surface_decompose.hpp>
#include <acd/version.hpp>
