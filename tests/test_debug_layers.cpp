// Debug layers (DebugLayer, shadows/technique.h): the shared stages' pictures of their work,
// published only when RenderContext::debug_layers asks, without changing the frame.
#include <penumbra/penumbra.h>

#include <gtest/gtest.h>

#include <string>

namespace test_debug_layers {

using namespace penumbra;

constexpr int kWidth = 160, kHeight = 107;

FrameResult render(const std::string& technique, bool layers) {
  static const Scene scene = loadScene("spheres");
  FrameOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.technique = TechniqueConfig(technique);
  // The wedges' umbra pass on the penumbra pass's 16-pixel tiles, so both count on one grid.
  if (technique == "wedge-3pass") options.technique.set("umbra-tile-size", "16");
  options.context.debug_layers = layers;
  return renderFrame(scene, options);
}

double sum(const Image<float>& image) {
  double total = 0;
  for (size_t i = 0; i < image.size(); ++i) total += image.data()[i];
  return total;
}

// Each culled tile adds 1 to every pixel of its tile, so its top-left pixel counts it once:
// the values at the tile origins add up to the culled tiles.
double atTileOrigins(const Image<float>& image, int tile_size) {
  double total = 0;
  for (int y = 0; y < image.height(); y += tile_size)
    for (int x = 0; x < image.width(); x += tile_size) total += image.at(x, y);
  return total;
}

const DebugLayer& layerOf(const FrameResult& frame, const char* name) {
  const DebugLayer* layer = findDebugLayer(frame.lights.at(0).debug_layers, name);
  if (layer == nullptr) throw Error(std::string("no layer ") + name);
  return *layer;
}

// Not asked, a technique publishes nothing; asked, its visibility stays bit for bit the same
// (drawing the layers must not touch the buffers the frame is made of).
TEST(DebugLayers, OnlyWhenAskedAndTheFrameUnchanged) {
  for (const char* technique : {"volume", "wedge-3pass", "wedge-1pass", "exact"}) {
    const FrameResult plain = render(technique, false);
    const FrameResult layered = render(technique, true);
    EXPECT_TRUE(plain.lights.at(0).debug_layers.empty()) << technique;
    EXPECT_FALSE(layered.lights.at(0).debug_layers.empty()) << technique;
    EXPECT_TRUE(plain.lights[0].visibility == layered.lights[0].visibility)
        << technique << ": the layers changed the visibility";
    EXPECT_TRUE(plain.total.sameCounters(layered.total)) << technique;
  }
}

// The silhouette edges are drawn (the counters say there are some), and the culled-tiles layer
// holds exactly the tiles the counter counts: a missed or an extra tile would show.
TEST(DebugLayers, VolumeSilhouettesAndCulledTilesMatchTheCounters) {
  const FrameResult frame = render("volume", true);
  ASSERT_GT(frame.total.silhouette_edges, 0u);
  EXPECT_GT(sum(layerOf(frame, kSilhouetteEdgesLayer).values), 0.0);
  ASSERT_GT(frame.total.tiles_culled, 0u);
  // The volume's culling tiles are its bin tiles, 32 pixels (StencilOptions::cull_level).
  EXPECT_EQ(atTileOrigins(layerOf(frame, kCulledTilesLayer).values, 32),
            double(frame.total.tiles_culled));
}

// The wedges: the footprint layer adds up to the pixels tested against a wedge
// (penumbra_tests), and the culled tiles of both passes (16-pixel tiles) to tiles_culled.
TEST(DebugLayers, WedgeFootprintsAndCulledTilesMatchTheCounters) {
  const FrameResult frame = render("wedge-3pass", true);
  ASSERT_GT(frame.total.penumbra_tests, 0u);
  EXPECT_EQ(sum(layerOf(frame, kWedgeFootprintsLayer).values),
            double(frame.total.penumbra_tests));
  ASSERT_GT(frame.total.tiles_culled, 0u);
  EXPECT_EQ(atTileOrigins(layerOf(frame, kCulledTilesLayer).values, 16),
            double(frame.total.tiles_culled));
  EXPECT_GT(sum(layerOf(frame, kSilhouetteEdgesLayer).values), 0.0);
}

// exact's footprints are its binned potential edges: a pixel in penumbra (visibility strictly
// between 0 and 1) has some edge's projection over part of the light, so that edge must be
// binned at its tile; a pixel in penumbra with no binned edge would mean the layer (or the
// binning) missed a tile. The stencil's layers come with them.
TEST(DebugLayers, ExactFootprintsHoldEveryPenumbraPixel) {
  const FrameResult frame = render("exact", true);
  const Image<float>& footprints = layerOf(frame, kWedgeFootprintsLayer).values;
  const Image<float>& visibility = frame.lights.at(0).visibility;
  int penumbra = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (!(visibility.at(x, y) > 0.0f && visibility.at(x, y) < 1.0f)) continue;
      ++penumbra;
      if (!(footprints.at(x, y) > 0.0f)) ++outside;
    }
  EXPECT_GT(penumbra, 0);
  EXPECT_EQ(outside, 0) << "penumbra pixels outside every binned edge's tile";
  EXPECT_GT(sum(layerOf(frame, kSilhouetteEdgesLayer).values), 0.0);
  EXPECT_NE(findDebugLayer(frame.lights.at(0).debug_layers, kCulledTilesLayer), nullptr);
}

TEST(DebugLayers, LayerLookupAndSizeCheck) {
  std::vector<DebugLayer> layers;
  Image<float>& a = debugLayer(layers, "a", "first", 4, 3);
  a.at(1, 1) = 2.0f;
  EXPECT_EQ(&debugLayer(layers, "a", "", 4, 3), &layers[0].values);
  EXPECT_EQ(layers[0].values.at(1, 1), 2.0f) << "asking again must not clear the layer";
  EXPECT_THROW(debugLayer(layers, "a", "", 5, 3), Error) << "a layer at another size";
  EXPECT_EQ(findDebugLayer(layers, "b"), nullptr);
}

}  // namespace test_debug_layers
