// acd evaluate MODEL HULLS.obj: IoU, union volume and surface distances of any set of hulls (acd's,
// CoACD's, V-HACD's) against the model, as a table or as JSON (acd::evaluateModel).
#include "evaluate.hpp"

#include "exit_codes.hpp"
#include "scene_reader.hpp"

#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/report.hpp>

#include <cstdio>
#include <iostream>
#include <string>

namespace acdcli {

namespace {

struct EvaluateArgs {
  std::string model, hulls;
  acd::EvaluateOptions options;
  bool json = false;
};
EvaluateArgs args;

int evaluateHulls(const std::string& modelPath, const std::string& hullPath, acd::EvaluateOptions options, bool asJson) {
  acd::ReadResult r = readModel(modelPath);
  if (!r.status.ok()) return fail(modelPath, r.status);
  acd::ObjObjects hulls = acd::readObjObjects(hullPath);
  if (!hulls.status.ok()) return fail(hullPath, hulls.status);
  const acd::Evaluation e = acd::evaluateModel(r.mesh, hulls.objects, options);
  if (!e.status.ok()) return fail("evaluate", e.status);
  if (asJson) {
    std::cout << acd::evaluationJson(modelPath, hullPath, e);
    return kOk;
  }
  std::printf("  model            %s\n  hulls            %s (%d hulls)\n", modelPath.c_str(), hullPath.c_str(), e.hulls);
  std::printf("  model volume     %.5f   (normalised units)\n", e.modelVolume);
  std::printf("  union volume     %.5f ± %.5f   (%.4f × model)\n", e.unionVolume, e.unionVolumeStdErr, e.unionToModelRatio);
  std::printf("  IoU              %.4f ± %.4f\n", e.iou, e.iouStdErr);
  std::printf("  misclassified    %.4f %% of sampled points\n", 100.0 * e.misclassifiedShare);
  std::printf("  hulls stick out  max %.4f, mean %.5f\n", e.hullOutsideMax, e.hullOutsideMean);
  std::printf("  model uncovered  max %.4f, mean %.5f\n", e.modelToHullsMax, e.modelToHullsMean);
  std::printf("  time             %.2f s\n", e.seconds);
  return kOk;
}

}  // namespace

CLI::App* addEvaluateCommand(CLI::App& app) {
  acd::EvaluateOptions& eo = args.options;
  auto* eval = app.add_subcommand("evaluate", "Measure a set of convex hulls (one OBJ object each) against a model");
  eval->add_option("model", args.model, "The closed model")->required();
  eval->add_option("hulls", args.hulls, "OBJ with one object per hull (acd, CoACD, V-HACD output)")->required();
  eval->add_option("--samples", eo.volumeSamples, "Monte-Carlo points for volumes and IoU")->capture_default_str();
  eval->add_option("--surface-samples", eo.surfaceSamples, "Surface points for the distance measures")->capture_default_str();
  eval->add_option("--seed", eo.seed, "Random seed")->capture_default_str();
  eval->add_option("--threads", eo.threads, "Worker threads, 0 = all cores")->capture_default_str();
  eval->add_flag("--json", args.json, "Print JSON instead of a table");
  return eval;
}

int runEvaluate() {
  if (args.options.volumeSamples <= 0 || args.options.surfaceSamples <= 0)
    return fail("invalid parameter", acd::Status::error(acd::StatusCode::InvalidParameter, "samples must be positive"));
  return evaluateHulls(args.model, args.hulls, args.options, args.json);
}

}  // namespace acdcli
