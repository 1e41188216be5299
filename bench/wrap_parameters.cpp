// wrap_parameters MODEL... : the alpha wrap of each model at several (alpha, offset) pairs in
// normalised units, with its two-sided Hausdorff distance to the model, face count and time.
// The table behind the choice in acd::wrapParametersFor (docs/ALGORITHM.md, "The watertight wrap").
#include <acd/algo/alpha_wrap.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv) {
  // --grid A:O,A:O,... replaces the default (alpha, offset) pairs.
  std::vector<std::pair<double, double>> grid = {{0.1, 0.01},    {0.05, 0.005}, {0.05, 0.0025},
                                                 {0.025, 0.0025}, {0.02, 0.002}, {0.0125, 0.00125}};
  int first = 1;
  if (argc > 2 && std::string(argv[1]) == "--grid") {
    grid.clear();
    std::string spec = argv[2];
    for (std::size_t at = 0; at < spec.size();) {
      const std::size_t comma = std::min(spec.find(',', at), spec.size());
      const std::string item = spec.substr(at, comma - at);
      const std::size_t colon = item.find(':');
      grid.emplace_back(std::stod(item.substr(0, colon)), std::stod(item.substr(colon + 1)));
      at = comma + 1;
    }
    first = 3;
  }
  std::printf("| model | faces | alpha | offset | wrap faces | Hausdorff | wrap to input | input to wrap | wrap (s) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int i = first; i < argc; ++i) {
    const acd::ReadResult r = acd::readMesh(argv[i]);
    if (!r.status.ok()) {
      std::fprintf(stderr, "%s\n", r.status.message.c_str());
      return 1;
    }
    const acd::Normalization n = acd::minimumSphereNormalization(r.mesh);
    const acd::TriMesh m = acd::applyNormalization(r.mesh, n);
    for (const auto& [alpha, offset] : grid) {
      const acd::Wrap w = acd::alphaWrap(m, alpha, offset);
      const acd::SurfaceDistance d = acd::surfaceDistance(w.mesh, m);
      std::printf("| %s | %zu | %g | %g | %zu | %.4f | %.4f | %.4f | %.2f |\n", argv[i], m.faces.size(), alpha, offset,
                  w.mesh.faces.size(), d.hausdorff(), d.aToB, d.bToA, w.seconds);
      std::fflush(stdout);
    }
  }
  return 0;
}
