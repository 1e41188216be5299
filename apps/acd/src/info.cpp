// acd info MODEL: the mesh's diagnosis (counts, manifoldness, orientation, genus, volume,
// self-intersections) and, step by step, what `acd decompose` would repair or refuse.
#include "info.hpp"

#include "exit_codes.hpp"
#include "scene_reader.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/robust.hpp>

#include <cstdio>
#include <string>

namespace acdcli {

namespace {

std::string infoModel;

int diagnoseModel(const std::string& path) {
  acd::ReadResult r = readModel(path);
  if (!r.status.ok()) return fail(path, r.status);
  const acd::MeshDiagnosis d = acd::diagnose(r.mesh);
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::printf("%s\n", path.c_str());
  std::printf("  vertices              %d\n", d.vertices);
  std::printf("  faces                 %d\n", d.faces);
  std::printf("  edges                 %d\n", d.edges);
  std::printf("  boundary edges        %d\n", d.boundaryEdges);
  std::printf("  non-manifold edges    %d\n", d.nonManifoldEdges);
  std::printf("  non-manifold vertices %d\n", d.nonManifoldVertices);
  std::printf("  components            %d\n", d.components);
  std::printf("  consistent orientation %s\n", yes(d.orientationConsistent));
  std::printf("  degenerate faces      %d\n", d.degenerateFaces);
  std::printf("  duplicate faces       %d\n", d.duplicateFaces);
  std::printf("  duplicate vertices    %d\n", d.duplicateVertices);
  std::printf("  non-finite vertices   %d\n", d.nonFiniteVertices);
  std::printf("  closed                %s\n", yes(d.closed));
  if (d.genus >= 0)
    std::printf("  genus                 %d\n", d.genus);
  else
    std::printf("  genus                 undefined (not closed)\n");
  std::printf("  volume                %.9g%s\n", d.volume, d.closed ? "" : " (not closed: meaningless)");
  std::printf("  area                  %.9g\n", d.area);
  std::printf("  bounding box          [%g %g %g] - [%g %g %g]\n", d.bbox.lo.x(), d.bbox.lo.y(), d.bbox.lo.z(),
              d.bbox.hi.x(), d.bbox.hi.y(), d.bbox.hi.z());
  if (!d.firstProblem.empty()) std::printf("  first problem         %s\n", d.firstProblem.c_str());
  const int pairs = d.closed && d.nonManifoldEdges == 0 ? acd::countSelfIntersections(r.mesh) : -1;
  if (pairs >= 0) std::printf("  self-intersections    %d face pairs\n", pairs);
  // What `acd decompose` would do, step by step (the same code, without building the wrap).
  const acd::PreparedModel p = acd::prepareModel(r.mesh, acd::DecomposeOptions{}, false);
  for (const auto& line : p.repairs) std::printf("  repair                %s\n", line.c_str());
  if (pairs > 0)
    std::printf("  repair                the surface passes through itself: a shell left above tau is repaired "
                "around the crossings, or decomposed through its wrap\n");
  if (!p.status.ok())
    std::printf("  solid decomposition   refused: %s\n", p.status.message.c_str());
  else if (!p.wrapReason.empty())
    std::printf("  solid decomposition   possible, through a watertight wrap (--no-wrap refuses it)\n");
  else
    std::printf("  solid decomposition   possible%s\n", p.repairs.empty() ? "" : " after the repairs above");
  return kOk;
}

}  // namespace

CLI::App* addInfoCommand(CLI::App& app) {
  auto* info = app.add_subcommand("info", "Diagnose a mesh: counts, manifoldness, orientation, genus, volume");
  info->add_option("model", infoModel, "Input mesh")->required();
  return info;
}

int runInfo() { return diagnoseModel(infoModel); }

}  // namespace acdcli
