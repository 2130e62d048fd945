// penumbra convert IN OUT.obj: a mesh file read by our loader, written as OBJ. This is how
// scripts/fetch-models.sh turns a fetched PLY into the OBJ the scene files name.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "core/error.h"
#include "scene/load_mesh.h"
#include "scene/write_obj.h"

namespace penumbra::cli {
namespace {

struct ConvertArgs {
  std::string input;
  std::string output;
  std::vector<std::string> comments;
  bool quiet = false;
};

int runConvert(const ConvertArgs& args) {
  PENUMBRA_CHECK(args.output.size() > 4 && args.output.substr(args.output.size() - 4) == ".obj",
                 "output '{}' must be a .obj file", args.output);
  const Mesh mesh = loadMesh(args.input);
  writeObj(args.output, mesh, args.comments);
  if (!args.quiet) {
    std::cout << fmt::format("wrote {}: {} triangles, {} vertices\n", args.output,
                             mesh.triangleCount(), mesh.positions.size());
  }
  return 0;
}

}  // namespace

Subcommand addConvertCommand(CLI::App& app) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "Write a mesh file as OBJ as our loader reads it (welded, triangles only)");
  cmd->add_option("input", args->input, "Mesh file (OBJ, PLY, glTF, ...)")->required();
  cmd->add_option("output", args->output, "OBJ file to write")->required();
  cmd->add_option("--comment", args->comments, "A '#' line to start the file with (repeatable)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing");
  return {cmd, [args] { return runConvert(*args); }};
}

}  // namespace penumbra::cli
