#include "viewer_args.h"

#include <fmt/format.h>

#include <penumbra/penumbra.h>

namespace penumbra::viewer {

namespace {

int integerArg(const std::string& flag, const std::string& value, int min, int max) {
  return int(parseInteger(value, min, max, flag));
}

}  // namespace

std::string viewerUsage() {
  return R"(penumbra view SCENE [--technique NAME] [technique options] [options]

SCENE: a built-in scene (penumbra scenes), a .json scene file or a mesh file.
Technique options are those of `penumbra render` (penumbra techniques NAME lists them).

Options:
  --width W, --height H     frame size (default: the scene's)
  --threads N               worker threads (0: all cores)
  --scalar                  scalar twins of every SIMD kernel
  --script FILE             replay input events (apps/viewer/input_script.h)
  --quit-after N            quit N window frames after the script's end (headless runs, tests)
  --screenshot FILE.png     on quitting, the frame area as `penumbra render` writes it
  --visibility FILE.exr     with it, every light's visibility
  --window-screenshot FILE.png   on quitting, the whole window
  --save-scene FILE.json    on quitting, the camera and lights as a scene file
  --bench N                 render N full frames back to back through the window loop,
                            print their median time, quit

Mouse: left drag orbits, right (or middle) drag pans, the wheel zooms; ctrl + left drag moves
the selected light in its horizontal plane, ctrl + shift + left drag along the vertical.
Keys: s saves a screenshot and the scene into out/, l selects the next light, escape quits.
)";
}

ViewerArgs parseViewerArgs(const std::vector<std::string>& argv) {
  ViewerArgs args;
  // The technique first: its options are read by its own option table.
  for (size_t i = 0; i + 1 < argv.size(); ++i) {
    if (argv[i] == "--technique") args.technique = argv[i + 1];
  }
  const TechniqueInfo& technique = findTechnique(args.technique);
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    const auto value = [&]() -> const std::string& {
      PENUMBRA_CHECK(i + 1 < argv.size(), "{} needs a value", arg);
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      args.help = true;
    } else if (arg == "--technique") {
      (void)value();
    } else if (arg == "--width") {
      args.width = integerArg(arg, value(), 1, 8192);
    } else if (arg == "--height") {
      args.height = integerArg(arg, value(), 1, 8192);
    } else if (arg == "--threads") {
      args.threads = integerArg(arg, value(), 0, 1024);
    } else if (arg == "--scalar") {
      args.scalar = true;
    } else if (arg == "--script") {
      args.script = value();
    } else if (arg == "--quit-after") {
      args.quit_after = integerArg(arg, value(), 1, 1000000);
    } else if (arg == "--screenshot") {
      args.screenshot = value();
    } else if (arg == "--visibility") {
      args.visibility = value();
    } else if (arg == "--window-screenshot") {
      args.window_screenshot = value();
    } else if (arg == "--save-scene") {
      args.save_scene = value();
    } else if (arg == "--bench") {
      args.bench_frames = integerArg(arg, value(), 1, 100000);
    } else if (arg.rfind("--", 0) == 0) {
      const OptionSpec* spec = technique.options.find(arg.substr(2));
      PENUMBRA_CHECK(spec != nullptr, "unknown option '{}' (technique '{}' has no such option; "
                     "penumbra techniques {} lists its options)", arg, technique.name,
                     technique.name);
      args.technique_options.emplace_back(spec->name,
                                          spec->kind == OptionKind::Flag ? "true" : value());
    } else {
      PENUMBRA_CHECK(args.scene.empty(), "one scene only (got '{}' and '{}')", args.scene, arg);
      args.scene = arg;
    }
  }
  if (!args.help) PENUMBRA_CHECK(!args.scene.empty(), "no scene given (run with --help)");
  for (const auto& [flag, path, ext] :
       {std::tuple{"--screenshot", args.screenshot, ".png"},
        std::tuple{"--window-screenshot", args.window_screenshot, ".png"},
        std::tuple{"--visibility", args.visibility, ".exr"},
        std::tuple{"--save-scene", args.save_scene, ".json"}}) {
    PENUMBRA_CHECK(path.empty() || (path.size() > 4 && path.substr(path.size() - std::string(ext).size()) == ext),
                   "{} '{}' must be a {} file", flag, path, ext);
  }
  PENUMBRA_CHECK(args.visibility.empty() || !args.screenshot.empty(),
                 "--visibility is written with --screenshot");
  return args;
}

}  // namespace penumbra::viewer
