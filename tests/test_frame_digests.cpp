// Golden frame digests: every technique, in the configurations that reach its code paths, on
// every built-in scene and every scene file, reduced to its exact work counters and a hash of
// each light's visibility, and compared with recorded values (first recorded from the code before
// the technique registry replaced TechniqueOptions / TechniqueKind, commit 2db1c58). A refactor
// that changes no output leaves every digest as it was; one that does names the scene, the
// configuration, the light and the value that moved.
//
// Record (only when an output change is intended, and say why in the commit):
//   PENUMBRA_RECORD_DIGESTS=$PWD/tests/golden/frame_digests.json build/penumbra_tests
//     --gtest_filter='FrameDigest*'   (one command line)
// Run it from the test binary, not from ctest: the scenes' tests merge into the file one after
// the other, and parallel ctest processes would race on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/stats.h"
#include "render/frame.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"

namespace penumbra::testing {
namespace test_frame_digests {

using nlohmann::json;

// Small frames: 18 scenes x 21..31 configurations must stay cheap under the sanitizers too, and
// a bit flip anywhere in a 128 x 86 frame changes its hash as surely as in a large one. 86 rows
// are not a multiple of any tile size, so partial tiles are exercised at every level.
constexpr int kWidth = 128;
constexpr int kHeight = 86;

// The oracle's visibility mean may move by this much between machines (see compareLight).
constexpr double kReferenceMeanTolerance = 1e-4;

// One configuration in plain values. Nothing here is a technique's options field or enum, so the
// configurations, their keys, the digests and the golden file stay as they are when the
// technique API changes; only frameOptionsFor below translates them.
struct DigestConfig {
  std::string technique;  // "volume", "wedge-2002", "wedge-3pass", "wedge-1pass", "reference"
  std::string volume_mode = "auto";  // "auto", "zpass", "zfail"
  std::string cull = "full";         // "none", "zmax", "full"
  int tile_level = 4;                // culling tiles of 2^tile_level pixels (16 x 16)
  bool two_level = true;             // two-level stencil
  bool smooth = false;               // smooth falloff 3s^2 - 2s^3
  int rays = 16;                     // oracle rays per pixel (soft)
  bool hard = false;                 // oracle: one ray to the light centre
  // Every other technique: its defaults, changed only by these options (as on the command
  // line). A configuration with a `variant` name is one of these.
  std::string variant{};
  std::vector<std::pair<std::string, std::string>> options{};
};

// The techniques whose configurations are spelled by the fields above (volume, the wedges and
// the oracle), recorded first.
bool hasLegacyFields(const DigestConfig& c) { return c.variant.empty(); }

// THE ONLY PLACE IN THIS FILE THAT USES THE TECHNIQUE API. When it changes, port this function
// and nothing else: the golden file then proves that the same configuration renders the same
// frame before and after. Options are given as on the command line, and only those the
// technique has (shadows/technique.h); fields a configuration does not name (seed, the umbra
// pass's tile size) keep the technique's defaults on purpose: a refactor that changes a default
// changes what users get, and the digests should show it.
FrameOptions frameOptionsFor(const DigestConfig& config) {
  FrameOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.context.threads = 0;  // all cores: the digests must not depend on the thread count
  options.context.simd = true;  // SIMD vs scalar identity is tested elsewhere (conformance suite)
  // The counters record the work of every caster; culling leaves the bits as they are and only
  // lowers those counters (tests/test_caster_culling.cpp compares the frames on and off).
  options.context.caster_culling = CasterCullingMode::Off;
  TechniqueConfig& t = options.technique;
  t = TechniqueConfig(config.technique);
  const auto setIfTaken = [&](const std::string& option, const std::string& value) {
    if (t.info().options.find(option) != nullptr) t.set(option, value);
  };
  if (!hasLegacyFields(config)) {
    for (const auto& [option, value] : config.options) t.set(option, value);
    return options;
  }
  setIfTaken("volume-mode", config.volume_mode);
  setIfTaken("cull", config.cull);
  setIfTaken("tile-size", std::to_string(1 << config.tile_level));
  setIfTaken("one-level-stencil", config.two_level ? "false" : "true");
  setIfTaken("smooth", config.smooth ? "true" : "false");
  setIfTaken("rays", std::to_string(config.rays));
  setIfTaken("hard", config.hard ? "true" : "false");
  return options;
}

const char* onOff(bool value) { return value ? "on" : "off"; }

// The stable name of a configuration in the golden file and in messages: it names every value
// the technique reads, e.g. "wedge-3pass/cull=full/tile=16/two-level=on/smooth=off".
std::string configKey(const DigestConfig& c) {
  if (!hasLegacyFields(c)) return c.technique + "/" + c.variant;
  if (c.technique == "volume") {
    return fmt::format("volume/mode={}/two-level={}", c.volume_mode, onOff(c.two_level));
  }
  if (c.technique == "reference") {
    return c.hard ? std::string("reference/hard") : fmt::format("reference/rays={}", c.rays);
  }
  return fmt::format("{}/cull={}/tile={}/two-level={}/smooth={}", c.technique, c.cull,
                     1 << c.tile_level, onOff(c.two_level), onOff(c.smooth));
}

// The oracle's visibility comes from Embree, which picks its traversal and intersection kernels
// by the CPU it runs on (SSE, AVX2, AVX-512): another machine may decide a grazing ray the other
// way, so its bits are not a property of our code. Its counters are (rays are counted before
// Embree sees them), and so is its mean up to a few such rays.
// Everything else is our own arithmetic (no -march, no FP contraction, SIMD kernels equal to
// their scalar twins), so its bits are the same on every x86-64 machine, with one assumption:
// glibc picks FMA variants of some libm functions (sin, cos: the generators) by CPU, and every
// machine these tests have run on has FMA. A mismatch on a machine without it points here.
bool visibilityIsExact(const DigestConfig& c) { return c.technique != "reference"; }

// The configurations of one scene. Built-in scenes get full culling at every tile size, scene
// files (up to 200k triangles) only 8 x 8 and 64 x 64 besides the default 16 x 16.
std::vector<DigestConfig> digestConfigs(bool every_tile_level) {
  std::vector<DigestConfig> configs;
  for (const char* mode : {"auto", "zpass", "zfail"}) {
    configs.push_back({.technique = "volume", .volume_mode = mode});
  }
  configs.push_back({.technique = "volume", .two_level = false});
  configs.push_back({.technique = "wedge-2002"});
  for (const char* technique : {"wedge-3pass", "wedge-1pass"}) {
    for (const char* cull : {"none", "zmax", "full"}) {
      configs.push_back({.technique = technique, .cull = cull});
    }
    configs.push_back({.technique = technique, .two_level = false});
    configs.push_back({.technique = technique, .smooth = true});
    const std::vector<int> levels =
        every_tile_level ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8} : std::vector<int>{3, 6};
    for (int level : levels) {
      if (level == 4) continue;  // the default level, above
      configs.push_back({.technique = technique, .tile_level = level});
    }
  }
  configs.push_back({.technique = "reference", .hard = true});
  configs.push_back({.technique = "reference", .rays = 16});
  // Every other technique at its defaults, and the options that switch its code paths.
  const auto add = [&](const char* technique, const char* variant,
                       std::vector<std::pair<std::string, std::string>> options = {}) {
    configs.push_back({.technique = technique, .variant = variant, .options = std::move(options)});
  };
  add("depth-bounds-volume", "default");
  add("hierarchical-volume", "default");
  add("hierarchical-volume", "tile=8/dense-limit=0", {{"tile-size", "8"}, {"dense-limit", "0"}});
  add("hierarchical-volume", "mode=zfail", {{"volume-mode", "zfail"}});
  add("coverage", "default");
  add("exact", "default");
  add("exact", "samples=64/tile=8", {{"samples", "64"}, {"tile-size", "8"}});
  add("heckbert-herf", "default");
  for (const char* mask : {"mask-alpha", "mask-colour"}) {
    add(mask, "default");
    add(mask, "scale=4", {{"mask-scale", "4"}});
  }
  add("shadow-map", "default");
  add("shadow-map", "pcf=1/size=256", {{"pcf-kernel", "1"}, {"shadow-map-size", "256"}});
  add("shadow-map", "projection=cube", {{"projection", "cube"}});
  add("shadow-map", "stencil-limit", {{"stencil-limit", "true"}});
  add("pcss", "default");
  add("alias-free", "default");
  return configs;
}

// --- Digests: plain JSON built from a FrameResult, with no knowledge of technique options. ---

// FNV-1a, 64 bits, over the little-endian bytes of each value's bits in row-major order: any
// changed bit of any pixel changes it, and it is the same on every host.
template <typename T>
uint64_t fnv1a(const Image<T>& image) {
  static_assert(sizeof(T) == 4);
  uint64_t hash = 0xcbf29ce484222325ull;
  for (size_t i = 0; i < image.size(); ++i) {
    const uint32_t bits = std::bit_cast<uint32_t>(image[i]);
    for (int byte = 0; byte < 4; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xffu;
      hash *= 0x100000001b3ull;
    }
  }
  return hash;
}

std::string hex(uint64_t value) { return fmt::format("{:016x}", value); }

json countersJson(const Stats& stats) {
  json counters = json::object();
  // Every counter by its name, shared or the technique's own; timings are not deterministic:
  // left out.
  stats.forEachCounter(
      [&](const char* name, const char*, uint64_t value) { counters[name] = value; });
  return counters;
}

double meanOf(const Image<float>& image) {
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) sum += image[i];
  return image.empty() ? 0.0 : sum / double(image.size());
}

// The eye pass: the same for every configuration of a scene (it does not depend on the
// technique), so stored once per scene and checked against every frame.
json eyeDigest(const FrameResult& frame) {
  return {{"counters", countersJson(frame.eye_stats)},
          {"depth_fnv1a", hex(fnv1a(frame.eye.depth.depth))},
          {"primitive_fnv1a", hex(fnv1a(frame.eye.primitive))},
          {"width", frame.eye.depth.depth.width()},
          {"height", frame.eye.depth.depth.height()}};
}

// One entry per light, in the scene's order.
json lightsDigest(const FrameResult& frame) {
  json lights = json::array();
  for (const auto& light : frame.lights) {
    lights.push_back({{"counters", countersJson(light.stats)},
                      {"visibility_fnv1a", hex(fnv1a(light.visibility))},
                      {"width", light.visibility.width()},
                      {"height", light.visibility.height()},
                      {"mean", meanOf(light.visibility)}});
  }
  return lights;
}

// A scene's digest: {"eye": ..., "configs": {key: {"lights": [...]}}}. A frame whose eye pass
// differs from the first frame's is a failure of its own (the eye pass would depend on the
// technique), reported under the configuration's key.
json digestScene(const Scene& scene, const std::string& scene_key,
                 const std::vector<DigestConfig>& configs) {
  json digest = {{"configs", json::object()}};
  for (size_t i = 0; i < configs.size(); ++i) {
    const DigestConfig& config = configs[i];
    const std::string key = configKey(config);
    FrameOptions options = frameOptionsFor(config);
    // Every other configuration with the eye pass's occlusion culling, which must change no
    // buffer (docs/occlusion-culling.md): the same depth, ids and visibility digests, while the
    // eye pass's work counters are the unculled pass's only without it (recorded: culling off).
    options.occlusion_culling = i % 2 == 1 ? OcclusionCullingMode::On : OcclusionCullingMode::Off;
    const FrameResult frame = renderFrame(scene, options);
    json eye = eyeDigest(frame);
    if (options.occlusion_culling == OcclusionCullingMode::On && digest.contains("eye"))
      eye["counters"] = digest["eye"]["counters"];
    if (!digest.contains("eye")) {
      digest["eye"] = eye;
    } else if (eye != digest["eye"]) {
      ADD_FAILURE() << "scene " << scene_key << ", config " << key
                    << ": the eye pass differs from the scene's first configuration's ("
                    << eye.dump() << " vs " << digest["eye"].dump() << ")";
    }
    EXPECT_FALSE(digest["configs"].contains(key)) << "two configurations named " << key;
    digest["configs"][key] = {{"lights", lightsDigest(frame)}};
  }
  return digest;
}

// --- Comparison -------------------------------------------------------------------------------

std::string goldenPath() {
  return (std::filesystem::path(PENUMBRA_SOURCE_DIR) / "tests" / "golden" / "frame_digests.json")
      .string();
}

std::string recordHint() {
  return fmt::format(
      "if the change is intended, record with PENUMBRA_RECORD_DIGESTS={} "
      "build/penumbra_tests --gtest_filter='FrameDigest*'",
      goldenPath());
}

std::string valueText(const json& value) {
  if (value.is_null()) return "(none)";
  return value.is_string() ? value.get<std::string>() : value.dump();
}

// A member of a golden object, or null where a hand-edited or truncated file lacks it (const
// operator[] on a missing key is undefined): the comparison then reports "(none)".
const json& field(const json& object, const std::string& name) {
  static const json kNone;
  return object.is_object() && object.contains(name) ? object[name] : kNone;
}

double meanField(const json& light) {
  const json& mean = field(light, "mean");
  return mean.is_number() ? mean.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// Differences between two counter objects, by name, in the union of both names. A counter one
// side lacks is no difference while the other side's is 0: a counter declared after the
// recording that none of the recorded configurations uses, or a technique's own counter
// (declared in its folder) that another technique's frame does not carry. Once it counts
// anything in a recorded configuration, it is reported.
void compareCounters(const std::string& where, const json& expected, const json& actual,
                     std::vector<std::string>& out) {
  std::set<std::string> names;
  for (const auto& [name, value] : expected.items()) names.insert(name);
  for (const auto& [name, value] : actual.items()) names.insert(name);
  for (const std::string& name : names) {
    const json& e = field(expected, name);
    const json& a = field(actual, name);
    if ((e.is_null() && a == json(0)) || (a.is_null() && e == json(0))) continue;
    if (e != a) {
      out.push_back(fmt::format("{}: counter {} expected {} actual {}", where, name,
                                valueText(e), valueText(a)));
    }
  }
}

void compareLight(const std::string& where, bool exact, const json& expected, const json& actual,
                  std::vector<std::string>& out) {
  compareCounters(where, field(expected, "counters"), field(actual, "counters"), out);
  for (const char* name : {"width", "height"}) {
    if (field(expected, name) != field(actual, name)) {
      out.push_back(fmt::format("{}: visibility {} expected {} actual {}", where, name,
                                valueText(field(expected, name)), valueText(field(actual, name))));
    }
  }
  const double e_mean = meanField(expected);
  const double a_mean = meanField(actual);
  if (exact) {
    const json& e_hash = field(expected, "visibility_fnv1a");
    const json& a_hash = field(actual, "visibility_fnv1a");
    if (e_hash != a_hash || !(e_mean == a_mean)) {
      out.push_back(fmt::format("{}: visibility hash expected {} actual {} (mean {:.9f} -> {:.9f})",
                                where, valueText(e_hash), valueText(a_hash), e_mean, a_mean));
    }
  } else if (!(std::abs(e_mean - a_mean) <= kReferenceMeanTolerance)) {
    // The hash is recorded but not compared: see visibilityIsExact.
    out.push_back(fmt::format("{}: mean visibility expected {:.9f} actual {:.9f} (tolerance {})",
                              where, e_mean, a_mean, kReferenceMeanTolerance));
  }
}

// Every difference between a scene's golden digest and the one just computed, one line each.
std::vector<std::string> compareScene(const std::string& scene_key, const json& expected,
                                      const json& actual,
                                      const std::vector<DigestConfig>& configs) {
  std::vector<std::string> out;
  const std::string scene_where = "scene " + scene_key;
  const json& e_eye = field(expected, "eye");
  const json& a_eye = field(actual, "eye");
  compareCounters(scene_where + ", eye pass", field(e_eye, "counters"), field(a_eye, "counters"),
                  out);
  for (const char* name : {"depth_fnv1a", "primitive_fnv1a", "width", "height"}) {
    if (field(e_eye, name) != field(a_eye, name)) {
      out.push_back(fmt::format("{}, eye pass: {} expected {} actual {}", scene_where, name,
                                valueText(field(e_eye, name)), valueText(field(a_eye, name))));
    }
  }
  const json& e_configs = field(expected, "configs");
  const json& a_configs = field(actual, "configs");
  std::set<std::string> keys;
  for (const DigestConfig& config : configs) {
    const std::string key = configKey(config);
    keys.insert(key);
    const std::string where = scene_where + ", config " + key;
    if (field(e_configs, key).is_null()) {
      out.push_back(fmt::format("{}: not in the golden file; {}", where, recordHint()));
      continue;
    }
    const json& e_lights = field(field(e_configs, key), "lights");
    const json& a_lights = field(field(a_configs, key), "lights");
    if (e_lights.size() != a_lights.size()) {
      out.push_back(fmt::format("{}: {} lights expected, {} rendered", where, e_lights.size(),
                                a_lights.size()));
      continue;
    }
    for (size_t i = 0; i < e_lights.size(); ++i) {
      compareLight(fmt::format("{}, light {}", where, i), visibilityIsExact(config), e_lights[i],
                   a_lights[i], out);
    }
  }
  // A configuration the test no longer renders would silently stop being checked.
  for (const auto& [key, value] : e_configs.items()) {
    if (!keys.contains(key)) {
      out.push_back(fmt::format("{}: golden config {} is no longer rendered", scene_where, key));
    }
  }
  return out;
}

json readJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return json();
  return json::parse(in);  // a broken file throws: the test fails naming the parse error
}

void writeJsonFile(const std::string& path, const json& doc) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  ASSERT_TRUE(out.good()) << "cannot write " << path;
  out << doc.dump(2) << "\n";  // pretty and with sorted keys (std::map): diffs stay readable
  out.close();
  ASSERT_FALSE(out.fail()) << "cannot write " << path;
}

// Merges one scene's digest into the record file, so that the scenes' tests accumulate. A file
// recorded at another frame size is started afresh.
void recordScene(const std::string& path, const std::string& scene_key, const json& digest) {
  json doc = readJsonFile(path);
  if (!doc.is_object() || doc.value("width", 0) != kWidth || doc.value("height", 0) != kHeight) {
    doc = json::object();
  }
  doc["width"] = kWidth;
  doc["height"] = kHeight;
  doc["about"] =
      "Golden frame digests of tests/test_frame_digests.cpp: per scene and configuration, exact "
      "work counters and FNV-1a 64 hashes of the visibility bits. Recorded, not hand-edited.";
  doc["scenes"][scene_key] = digest;
  writeJsonFile(path, doc);
}

const json& goldenDigests() {
  static const json golden = readJsonFile(goldenPath());
  return golden;
}

// --- Scenes -----------------------------------------------------------------------------------

struct SceneCase {
  std::string key;        // in the golden file: "spheres", "scenes/bunny-lowres.json",
                          // "tests/data/scenes/armadillo.json" (the path in the source tree)
  std::string test_name;  // gtest's: letters, digits and '_' only
  std::string file;       // empty for a built-in scene
};

// For gtest's listing and messages (it would print the struct's bytes).
void PrintTo(const SceneCase& scene_case, std::ostream* os) { *os << scene_case.key; }

std::vector<SceneCase> sceneCases() {
  std::vector<SceneCase> cases;
  for (const std::string& name : builtinSceneNames()) cases.push_back({name, name, ""});
  // The large built-in scenes at their smallest size (the default city is millions of
  // triangles; CI renders every technique on one block).
  for (const std::string& name : largeBuiltinSceneNames()) {
    cases.push_back({name + ":1", name + "_1", ""});
  }
  // scenes/ and tests/data/scenes/ (models the repository can neither ship nor fetch).
  const std::filesystem::path root(PENUMBRA_SOURCE_DIR);
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& folder :
       {root / "scenes", root / "tests" / "data" / "scenes"}) {
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    std::string test_name = "file_" + file.stem().string();
    std::replace_if(
        test_name.begin(), test_name.end(), [](char ch) { return !std::isalnum(uint8_t(ch)); },
        '_');
    cases.push_back({file.lexically_relative(root).generic_string(), test_name, file.string()});
  }
  return cases;
}

// The "models:" meshes a scene file names that cannot be read (modelPath()).
std::vector<std::string> missingModels(const std::string& scene_file) {
  std::ifstream in(scene_file);
  const json doc = json::parse(in);
  std::vector<std::string> missing;
  for (const auto& mesh : doc.value("meshes", json::array())) {
    const std::string name = mesh.value("file", "");
    if (name.starts_with("models:") && !std::filesystem::exists(modelPath(name.substr(7)))) {
      missing.push_back(name);
    }
  }
  return missing;
}

class FrameDigest : public ::testing::TestWithParam<SceneCase> {};

// Every technique configuration on this scene renders exactly the frames recorded in the golden
// file: the same work counters and the same visibility bits (the oracle: the same counters and
// mean). A failure means the code now computes something else for this scene: a refactor that
// should change no output changed one (the message names configuration, light and value), or an
// intended change that has not been recorded.
TEST_P(FrameDigest, MatchesGolden) {
  const SceneCase& c = GetParam();
  if (!c.file.empty()) {
    const std::vector<std::string> missing = missingModels(c.file);
    if (!missing.empty()) {
      GTEST_SKIP() << c.key << ": " << missing.front() << " not found in " << modelsDirectory()
                   << " (set PENUMBRA_MODELS)";
    }
  }
  const Scene scene = c.file.empty() ? builtinScene(c.key) : loadSceneFile(c.file);
  const std::vector<DigestConfig> configs = digestConfigs(c.file.empty());
  const json actual = digestScene(scene, c.key, configs);

  if (const char* record = std::getenv("PENUMBRA_RECORD_DIGESTS"); record && *record) {
    recordScene(record, c.key, actual);
    std::cout << "recorded " << configs.size() << " configurations of " << c.key << " in "
              << record << "\n";
    return;
  }
  const json& golden = goldenDigests();
  ASSERT_TRUE(golden.is_object()) << goldenPath() << " is missing; " << recordHint();
  ASSERT_EQ(golden.value("width", 0), kWidth) << "golden frame size differs; " << recordHint();
  ASSERT_EQ(golden.value("height", 0), kHeight) << "golden frame size differs; " << recordHint();
  ASSERT_TRUE(golden.contains("scenes") && golden["scenes"].contains(c.key))
      << "scene " << c.key << " is not in " << goldenPath() << "; " << recordHint();

  const std::vector<std::string> differences =
      compareScene(c.key, golden["scenes"][c.key], actual, configs);
  // The first differences in full, then a count: a broken kernel differs everywhere.
  constexpr size_t kShown = 40;
  std::ostringstream message;
  for (size_t i = 0; i < std::min(differences.size(), kShown); ++i) {
    message << "  " << differences[i] << "\n";
  }
  if (differences.size() > kShown) {
    message << "  ... and " << differences.size() - kShown << " more\n";
  }
  if (!differences.empty()) {
    ADD_FAILURE() << differences.size() << " differences from " << goldenPath() << ":\n"
                  << message.str();
  }
}

std::string sceneTestName(const ::testing::TestParamInfo<SceneCase>& param) {
  return param.param.test_name;
}

// No prefix: the tests are FrameDigest.MatchesGolden/<scene>, so --gtest_filter='FrameDigest*'
// selects them.
INSTANTIATE_TEST_SUITE_P(, FrameDigest, ::testing::ValuesIn(sceneCases()), sceneTestName);

// Each configuration has its own key: two under one key would overwrite each other's digest.
TEST(FrameDigestSetup, ConfigKeysAreUnique) {
  for (bool every_level : {false, true}) {
    std::set<std::string> keys;
    for (const DigestConfig& config : digestConfigs(every_level)) {
      EXPECT_TRUE(keys.insert(configKey(config)).second) << configKey(config);
    }
  }
}

}  // namespace test_frame_digests
}  // namespace penumbra::testing
