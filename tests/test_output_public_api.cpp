// The public header alone is enough for a user's program: load, render, measure.
#include <penumbra/penumbra.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace test_output_public_api {

// If the public header missed a module, this would not compile; if the frame's pieces did not
// fit together (one visibility buffer per light, colour of the view's size), it would fail.
TEST(OutputPublicApi, RendersAndMeasuresATinyFrame) {
  const penumbra::Scene scene = penumbra::loadScene("spheres");
  penumbra::FrameOptions options;
  options.width = 24;
  options.height = 16;
  options.technique = penumbra::TechniqueConfig("volume");
  const penumbra::FrameResult frame = penumbra::renderFrame(scene, options);
  ASSERT_EQ(frame.lights.size(), scene.lights.size());
  EXPECT_EQ(frame.color.width(), 24);
  EXPECT_EQ(frame.color.height(), 16);
  // The hard volume against the one-ray oracle, through the public API: the same shadow but
  // for ties on its boundary, and a shadow there is (a frame of lit pixels would agree too).
  options.technique = penumbra::TechniqueConfig("reference");
  options.technique.set("hard", "true");
  const penumbra::FrameResult oracle = penumbra::renderFrame(scene, options);
  const penumbra::ImageDifference d =
      penumbra::compareImages(frame.lights[0].visibility, oracle.lights[0].visibility, 0.5);
  EXPECT_EQ(d.pixels, 24u * 16u);
  EXPECT_LE(d.fraction_over_tolerance, 2.0 / (24 * 16)) << "more than two pixels disagree";
  int shadowed = 0;
  for (size_t i = 0; i < frame.lights[0].visibility.size(); ++i)
    shadowed += frame.lights[0].visibility[i] < 0.5f;
  EXPECT_GT(shadowed, 0) << "no shadow in the frame: the comparison above proves nothing";
}

// The umbrella header includes every public header: a header it left out would be shipped
// but unreachable through <penumbra/penumbra.h>, as the README promises it is.
TEST(OutputPublicApi, UmbrellaHeaderIncludesEveryPublicHeader) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(PENUMBRA_SOURCE_DIR) / "include" / "penumbra";
  std::set<std::string> included;
  std::ifstream umbrella(root / "penumbra.h");
  for (std::string line; std::getline(umbrella, line);) {
    const std::string prefix = "#include <penumbra/";
    if (line.starts_with(prefix))
      included.insert(line.substr(prefix.size(), line.size() - prefix.size() - 1));
  }
  int headers = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".h" || entry.path().filename() == "penumbra.h") continue;
    ++headers;
    const std::string name = fs::relative(entry.path(), root).generic_string();
    EXPECT_TRUE(included.contains(name)) << "penumbra.h does not include <penumbra/" << name << ">";
  }
  EXPECT_GT(headers, 20);
}

}  // namespace test_output_public_api
