// Camera and light paths ("path" in scene files; path.h): interpolation between keys, strict
// reading, writing back, and `penumbra render --path / --frame / --list-frames` with GNU
// parallel and the Slurm array script (scripts/render-path-*.sh).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "cli_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_path {

using test::contains;
using test::errorMessage;

// Three camera keys at uneven times and a light moving over a shorter span.
const char* kPathScene = R"({
  "meshes": [{"generator": "plane", "half_size": 4}, {"generator": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}],
  "lights": [{"center": [0, 5, 0], "radius": 0.2}, {"center": [3, 5, 0]}],
  "camera": {"position": [0, 3, 6], "target": [0, 0.5, 0], "fov": 40},
  "path": {"frames": 5,
           "camera": [{"time": 0, "position": [0, 3, 6], "target": [0, 0.5, 0]},
                      {"time": 1, "position": [4, 3, 4], "target": [0, 0.5, 0], "fov": 60},
                      {"time": 4, "position": [6, 3, 0], "target": [0, 1, 0]}],
           "lights": [{"light": 1, "keys": [{"time": 1, "center": [3, 5, 0]}, {"time": 2, "center": [-3, 5, 0]}]}]},
  "settings": {"width": 32, "height": 24}
})";

Scene parse(const std::string& text) { return parseSceneJson(text, "walk.json", ""); }

// Frames are evenly spaced from the first key time to the last (0, 1, 2, 3, 4 here); values
// are linear between keys and hold outside them. If interpolation were off, every frame of a
// walkthrough would show another view than the keys describe.
TEST(ScenePath, FramesInterpolateBetweenKeysAndHoldOutside) {
  Scene scene = parse(kPathScene);
  ASSERT_EQ(scene.path.frames, 5);
  EXPECT_EQ(scene.path.frameTime(0), 0.0f);
  EXPECT_EQ(scene.path.frameTime(4), 4.0f);
  applyPathFrame(scene, 1);  // on the second camera key; the light's first key
  EXPECT_EQ(scene.camera.position, vec3(4, 3, 4));
  EXPECT_EQ(scene.camera.fov_y, 60.0f);
  EXPECT_EQ(scene.lights[1].center, vec3(3, 5, 0));
  applyPathFrame(scene, 2);  // a third of the way from key 1 to key 2; the light's last key
  EXPECT_NEAR(glm::length(scene.camera.position - vec3(4 + 2.0f / 3, 3, 4 - 4.0f / 3)), 0.0f,
              1e-5f);
  EXPECT_NEAR(scene.camera.fov_y, 60.0f - 20.0f / 3, 1e-4f);  // the last key has the file's 40
  EXPECT_EQ(scene.lights[1].center, vec3(-3, 5, 0));
  applyPathFrame(scene, 0);
  EXPECT_EQ(scene.lights[1].center, vec3(3, 5, 0));  // held before its first key
  EXPECT_EQ(scene.lights[0].center, vec3(0, 5, 0));  // not on the path: stays
  EXPECT_TRUE(contains(errorMessage([&] { applyPathFrame(scene, 5); }), "frame 5 is out of range"));
}

std::string withPath(const std::string& path) {
  return std::string(
             R"({"meshes": [{"generator": "sphere"}], "lights": [{"center": [0, 5, 0]}], "path": )") +
         path + "}";
}

// Each bad path names the file and the key: a typo in a long walkthrough is found at once.
TEST(ScenePath, BadPathsNameTheFileAndKey) {
  const auto message = [](const std::string& path) {
    return errorMessage([&] { (void)parse(withPath(path)); });
  };
  EXPECT_TRUE(
      contains(message(R"({"camera": [{"time": 0, "position": [0, 0, 5], "target": [0, 0, 0]}]})"),
               "walk.json: path.frames: missing"));
  EXPECT_TRUE(contains(message(R"({"frames": 0, "camera": []})"),
                       "path.frames: must be in 1..1000000 (got 0)"));
  EXPECT_TRUE(contains(message(R"({"frames": 3})"),
                       "walk.json: path: moves neither the camera nor a light"));
  EXPECT_TRUE(contains(
      message(R"({"frames": 3, "camera": [{"time": 1, "position": [0, 0, 5], "target": [0, 0, 0]},
                                                           {"time": 1, "position": [0, 1, 5], "target": [0, 0, 0]}]})"),
      "path.camera[1].time: 1 must be greater than the previous key's time (1)"));
  EXPECT_TRUE(contains(
      message(
          R"({"frames": 3, "camera": [{"time": 0, "position": [0, 0, 5], "target": [0, 0, 5]}]})"),
      "path.camera[0]: position and target must differ"));
  EXPECT_TRUE(contains(
      message(
          R"({"frames": 3, "lights": [{"light": 1, "keys": [{"time": 0, "center": [0, 5, 0]}]}]})"),
      "path.lights[0].light: light 1 is out of range (the scene has 1 lights)"));
  EXPECT_TRUE(contains(
      message(R"({"frames": 3, "lights": [{"keys": [{"time": 0, "centre": [0, 5, 0]}]}]})"),
      "path.lights[0].keys[0].centre: unknown key"));
  // A file over a base that replaces the lights with fewer than the base's path moves.
  const std::string over = errorMessage([] {
    (void)parseSceneJson(R"({"base": "city:1", "lights": [{"center": [0, 50, 0]}],
                             "path": {"frames": 2, "lights": [{"light": 0, "keys": [{"time": 0, "center": [0, 9, 0]}]},
                                                              {"light": 1, "keys": [{"time": 0, "center": [0, 9, 0]}]}]}})",
                         "over.json", "");
  });
  EXPECT_TRUE(contains(over, "over.json: path.lights[1].light: light 1 is out of range")) << over;
}

// Written over a base and as a whole scene, the path reads back bit for bit: the viewer's saved
// files and writeSceneFile keep a walkthrough.
TEST(ScenePath, WrittenPathReadsBackBitForBit) {
  test::ScratchDir dir;
  Scene scene = parse(kPathScene);
  scene.path.camera[1].position = vec3(1.0f / 3.0f, 2.7f, 0.1f);
  const std::string whole = dir.path() + "/whole.json";
  writeSceneFile(whole, scene);
  const std::string over = dir.write("over.json", sceneOverBaseJson(scene, "whole.json"));
  for (const std::string& file : {whole, over}) {
    SCOPED_TRACE(file);
    const Scene back = loadSceneFile(file);
    ASSERT_EQ(back.path.frames, scene.path.frames);
    ASSERT_EQ(back.path.camera.size(), scene.path.camera.size());
    for (size_t k = 0; k < scene.path.camera.size(); ++k) {
      EXPECT_EQ(std::memcmp(&back.path.camera[k], &scene.path.camera[k], sizeof(CameraKey)), 0)
          << k;
    }
    ASSERT_EQ(back.path.lights.size(), 1u);
    EXPECT_EQ(back.path.lights[0].light, 1u);
    ASSERT_EQ(back.path.lights[0].keys.size(), 2u);
    EXPECT_EQ(
        std::memcmp(&back.path.lights[0].keys[1], &scene.path.lights[0].keys[1], sizeof(LightKey)),
        0);
  }
}

// The built-in city comes with a walkthrough and a moving sun.
TEST(ScenePath, CityHasAWalkthroughAndAMovingSun) {
  Scene scene = builtinScene("city:1");
  ASSERT_FALSE(scene.path.empty());
  EXPECT_GE(scene.path.camera.size(), 2u);
  ASSERT_EQ(scene.path.lights.size(), 1u);
  const vec3 sun_start = scene.lights[0].center;
  applyPathFrame(scene, scene.path.frames - 1);
  EXPECT_GT(glm::length(scene.lights[0].center - sun_start), 1.0f);
}

using PathCli = penumbra::testing::CliTest;

// --path writes one numbered file per frame; --frame K exactly frame K's file; --list-frames
// the job list. If --frame rendered another view than --path does for the same K, frames
// rendered by a batch engine would not make the sequence.
TEST_F(PathCli, PathFrameAndListFramesAgree) {
  const std::string scene = path("walk.json");
  std::ofstream(scene) << kPathScene;
  const auto all = run("render walk.json --path --technique volume -o seq/walk.png --quiet");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  for (int k = 0; k < 5; ++k) {
    EXPECT_TRUE(std::filesystem::exists(path(fmt::format("seq/walk.{:04d}.png", k)))) << k;
  }
  const auto one = run("render walk.json --frame 2 --technique volume -o one/walk.png --quiet");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(penumbra::testing::slurp(path("one/walk.0002.png")),
            penumbra::testing::slurp(path("seq/walk.0002.png")));
  EXPECT_NE(penumbra::testing::slurp(path("seq/walk.0001.png")),
            penumbra::testing::slurp(path("seq/walk.0002.png")));
  const auto list = run("render walk.json --list-frames");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_EQ(list.out, "0\n1\n2\n3\n4\n");

  const auto out_of_range = run("render walk.json --frame 5");
  EXPECT_NE(out_of_range.exit_code, 0);
  EXPECT_TRUE(contains(out_of_range.err,
                       "--frame 5 is out of range: the path of scene 'walk' has frames 0..4"))
      << out_of_range.err;
  const auto no_path = run("render spheres --path");
  EXPECT_NE(no_path.exit_code, 0);
  EXPECT_TRUE(contains(no_path.err, "scene 'spheres' has no camera or light path")) << no_path.err;
  const auto both = run("render walk.json --path --frame 1");
  EXPECT_NE(both.exit_code, 0);
  EXPECT_TRUE(contains(both.err, "give one")) << both.err;
}

// GNU parallel runs the frame list (scripts/render-path-parallel.sh) and the Slurm array script
// renders the task's frame: both must give the files `--path` gives, byte for byte.
TEST_F(PathCli, ParallelAndSlurmScriptsRenderThePathsFrames) {
  const std::string scene = path("walk.json");
  std::ofstream(scene) << kPathScene;
  ASSERT_EQ(run("render walk.json --path --technique volume -o seq/walk.png --quiet").exit_code, 0);
  ASSERT_EQ(std::system("command -v parallel >/dev/null"), 0)
      << "GNU parallel is not installed (scripts/setup-debian.sh installs it)";
  const std::string scripts = std::string(PENUMBRA_SOURCE_DIR) + "/scripts/";
  const std::string parallel = fmt::format(
      "cd '{}' && PENUMBRA='{}' '{}render-path-parallel.sh' walk.json par/walk.png 2 -- "
      "--technique volume "
      ">par.log 2>&1",
      dir_.string(), cli_, scripts);
  ASSERT_EQ(std::system(parallel.c_str()), 0) << penumbra::testing::slurp(path("par.log"));
  for (int k = 0; k < 5; ++k) {
    SCOPED_TRACE(k);
    const std::string name = fmt::format("walk.{:04d}.png", k);
    EXPECT_EQ(penumbra::testing::slurp(path("par/" + name)),
              penumbra::testing::slurp(path("seq/" + name)));
  }
  const std::string slurm = fmt::format(
      "cd '{}' && SLURM_ARRAY_TASK_ID=3 SLURM_CPUS_PER_TASK=1 PENUMBRA='{}' "
      "'{}render-path-slurm.sh' "
      "walk.json slurm/walk.png -- --technique volume >slurm.log 2>&1",
      dir_.string(), cli_, scripts);
  ASSERT_EQ(std::system(slurm.c_str()), 0) << penumbra::testing::slurp(path("slurm.log"));
  EXPECT_EQ(penumbra::testing::slurp(path("slurm/walk.0003.png")),
            penumbra::testing::slurp(path("seq/walk.0003.png")));
  EXPECT_FALSE(std::filesystem::exists(path("slurm/walk.0002.png")));
}

}  // namespace test_scene_path
}  // namespace penumbra
