// acd convert IN OUT (convert.hpp).
#include "convert.hpp"

#include "exit_codes.hpp"
#include "scene_reader.hpp"

#include <acd/io.hpp>

#include <string>

namespace acdcli {

namespace {

struct ConvertArgs {
  std::string in, out;
};
ConvertArgs args;

}  // namespace

CLI::App* addConvertCommand(CLI::App& app) {
  auto* c = app.add_subcommand("convert", "Write a mesh in another format (.off, .obj, .ply, .stl), as read: no repair");
  c->add_option("input", args.in, "Any mesh or scene acd reads (a scene's meshes are merged, transforms applied)")->required();
  c->add_option("output", args.out, "Output file; its extension picks the format")->required();
  return c;
}

int runConvert() {
  acd::ReadResult r = readModel(args.in);
  if (!r.status.ok()) return fail(args.in, r.status);
  const acd::Status s = acd::writeMesh(args.out, r.mesh);
  if (!s.ok()) return outputFailed(args.out + ": " + s.message);
  return kOk;
}

}  // namespace acdcli
