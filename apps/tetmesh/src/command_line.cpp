#include "command_line.hpp"

#include <appcli/exit_codes.hpp>

namespace tetmesh {

using appcli::kBadParameter;
using appcli::kOk;

int checkArgs(Args& a, TetFormat& format) {
  std::string formatName = a.format;
  if (formatName.empty() && !a.out.empty()) {
    const auto dot = a.out.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : a.out.substr(dot + 1);
    formatName = ext == "mesh" ? "mesh" : ext == "vtk" ? "vtk" : "tetgen";
  }
  if (!formatName.empty() && !parseTetFormat(formatName, format)) {
    return kConsole.failf(kBadParameter, "unknown --format '%s' (vtk, mesh or tetgen)", formatName.c_str());
  }
  if (!(a.options.tau > 0) || !std::isfinite(a.options.tau)) {
    return kConsole.failf(kBadParameter, "--tau must be positive, got %g", a.options.tau);
  }
  if (a.mesher == "auto" || a.mesher == "refine" || a.mesher == "complex") {
    a.options.mesher = a.mesher == "auto" ? Mesher::Auto : a.mesher == "refine" ? Mesher::Refine : Mesher::Complex;
  } else {
    return kConsole.failf(kBadParameter, "unknown --mesher '%s' (auto, refine or complex)", a.mesher.c_str());
  }
  if (!a.poly.empty() && a.options.mesher != Mesher::Complex) {
    return kConsole.fail(kBadParameter, "--poly writes the complex given to TetGen: it needs --mesher complex");
  }
  if ((a.options.clip || a.options.sharpAngle != 0) && a.options.mesher == Mesher::Complex) {
    return kConsole.fail(kBadParameter, "--clip and --sharp need the refinement (--mesher auto or refine)");
  }
  if (!(a.options.sharpAngle >= 0 && a.options.sharpAngle < 180)) {
    return kConsole.failf(kBadParameter, "--sharp must be an angle in degrees in [0, 180), got %g", a.options.sharpAngle);
  }
  if (a.options.surfaceDistance != -1 && !(a.options.surfaceDistance > 0 && std::isfinite(a.options.surfaceDistance))) {
    return kConsole.failf(kBadParameter, "--surface-distance must be a positive share of tau, got %g", a.options.surfaceDistance);
  }
  if (a.options.simplify != -1 && a.options.simplify != 0 && a.options.simplify < 4) {
    return kConsole.failf(kBadParameter, "--simplify must be at least 4 (a tetrahedron), got %d", a.options.simplify);
  }
  // Delaunay refinement is proven to end from a bound of 2 and ends in practice down to about
  // 1.2 (TetGen) and 1.5 (CGAL's Mesh_3, whose sliver passes follow); below, it may not.
  const double lowestQuality = a.options.mesher == Mesher::Complex ? 1.0 : 1.5;
  if (a.options.tetgen.radiusEdge != 0 && !(a.options.tetgen.radiusEdge >= lowestQuality)) {
    return kConsole.failf(kBadParameter, "--quality must be at least %g with --mesher %s (the refinement may not end below), or 0 for none; got %g",
                          lowestQuality, a.mesher.c_str(), a.options.tetgen.radiusEdge);
  }
  if (a.options.tetgen.maxVolume < 0 || !std::isfinite(a.options.tetgen.maxVolume)) {
    return kConsole.failf(kBadParameter, "--max-volume must be positive (or 0 for no bound), got %g", a.options.tetgen.maxVolume);
  }
  return kOk;
}

int deformOptions(const DeformArgs& d, DeformationOptions& o) {
  auto bad = [](const std::string& message) {
    return kConsole.fail(kBadParameter, message);
  };
  o.handle = d.handle, o.anchor = d.anchor;
  o.arap.maxIterations = d.iterations;
  o.arap.minWeight = d.minWeight;
  o.translate = !d.move.empty();
  if (o.translate) o.move = Vec3(d.move[0], d.move[1], d.move[2]);
  o.rotate = !std::isnan(d.angle);
  o.angleDegrees = d.angle;
  if (d.handle < 0 || d.anchor < 0) return bad("--deform-handle and --deform-anchor are component labels (1, 2, ...)");
  if (d.handle != 0 && d.handle == d.anchor)
    return bad("--deform-handle and --deform-anchor are the same component (" + std::to_string(d.handle) + ")");
  if (o.translate && o.rotate) return bad("--deform-move and --deform-angle cannot be used together");
  if ((o.translate && !o.move.allFinite()) || (o.rotate && !std::isfinite(d.angle)))
    return bad("--deform-move and --deform-angle must be finite numbers");
  if (d.iterations < 0) return bad("--deform-iterations must not be negative, got " + std::to_string(d.iterations));
  if (!(d.minWeight >= 0) || !std::isfinite(d.minWeight)) return bad("--deform-min-weight must be a number >= 0");
  return kOk;
}

}  // namespace tetmesh
