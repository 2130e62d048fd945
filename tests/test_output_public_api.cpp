// The public header alone is enough for a user's program: load, render, measure.
#include <penumbra/penumbra.h>

#include <gtest/gtest.h>

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
  const penumbra::ImageDifference d =
      penumbra::compareImages(frame.lights[0].visibility, frame.lights[0].visibility, 0.0);
  EXPECT_EQ(d.pixels, 24u * 16u);
  EXPECT_EQ(d.max_error, 0.0);
}

}  // namespace test_output_public_api
