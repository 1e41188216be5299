// The example of docs/API.md, built by the packaging test against an installed libacd alone:
// decompose a mesh file, check what the default promises, write the hulls.
//   consumer [MODEL [HULLS.obj]]      (no MODEL: an L-shaped solid)
#include <acd/acd.hpp>
#include <acd/algo/shapes.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  acd::TriMesh mesh = acd::shapes::lShape();
  if (argc > 1) {
    const acd::ReadResult in = acd::readMesh(argv[1]);  // OFF, OBJ, PLY, STL
    if (!in.status.ok()) return std::fprintf(stderr, "consumer: %s\n", in.status.message.c_str()), 2;
    mesh = in.mesh;
  }
  acd::DecomposeOptions options;  // the defaults are what the acd command uses
  options.tau = 0.05;             // in units of the model's radius
  const acd::Decomposition d = acd::decomposeRepaired(mesh, options);  // any mesh: repairs, shells, wrap
  if (!d.status.ok()) return std::fprintf(stderr, "consumer: %s\n", d.status.message.c_str()), 1;

  // The promise: every hull within tau of the model, and the model inside the hulls.
  std::vector<acd::TriMesh> hulls;
  std::vector<std::string> names;
  double excess = 0.0;
  for (const acd::Component& c : d.components) {
    hulls.push_back(c.hull);
    names.push_back("hull_" + std::to_string(hulls.size()));
    excess = std::max(excess, c.hullExcess);
  }
  const acd::Coverage outside = acd::inputOutsideHulls(mesh, d);
  if (argc > 2) {
    const acd::Status written = acd::writeObjObjects(argv[2], hulls, names);
    if (!written.ok()) return std::fprintf(stderr, "consumer: %s\n", written.message.c_str()), 5;
  }
  std::printf("acd %s: %zu components, hulls within %.3g of the model, model within %.3g of the hulls (tau %g)\n",
              ACD_VERSION, d.components.size(), excess, outside.max, options.tau);
  return excess <= options.tau && outside.max <= options.tau ? 0 : 8;
}
