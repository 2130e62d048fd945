// The viewer's UI model: techniques and their options come from the technique table, so a
// technique registered later (here, by this test binary) shows up with its options and no
// viewer code.
#include <gtest/gtest.h>

#include <algorithm>

#include "viewer_model.h"

namespace penumbra::viewer {
namespace test_viewer_model {

struct ProbeOptions {
  int taps = 3;
  bool mirror = false;
  double softness = 0.25;
  enum class Mode { Near, Far } mode = Mode::Near;
};

class ProbeTechnique : public PreparedTechnique {
 public:
  TechniqueResult render(const Light&, const View& view, const EyeBuffers&,
                         const RenderContext&) const override {
    TechniqueResult result;
    result.visibility = Image<float>(view.width, view.height, 1.0f);
    return result;
  }
};

// Registered once for the whole binary, as a program that brings its own technique would.
const bool kProbeRegistered = [] {
  TechniqueInfo info;
  info.name = "viewer-test-probe";
  info.summary = "a technique only this test binary knows";
  info.options = OptionTableBuilder<ProbeOptions>()
                     .integer("probe-taps", "taps", &ProbeOptions::taps, 1, 9)
                     .preview("2")
                     .flag("probe-mirror", "mirror", &ProbeOptions::mirror)
                     .number("probe-softness", "softness", &ProbeOptions::softness, 0.0, 1.0)
                     .choice("probe-mode", "near or far", &ProbeOptions::mode,
                             {{"near", ProbeOptions::Mode::Near}, {"far", ProbeOptions::Mode::Far}})
                     .build();
  info.prepare = [](const std::any&, const Scene&) { return std::make_unique<ProbeTechnique>(); };
  registerTechnique(std::move(info));
  return true;
}();

const TechniqueEntry* entryNamed(const ViewerModel& model, const std::string& name) {
  for (const TechniqueEntry& entry : model.techniques) {
    if (entry.info->name == name) return &entry;
  }
  return nullptr;
}

// If the panel's list were written by hand, the probe would be missing, or its options would:
// every control the panel draws comes from this list.
TEST(ViewerModel, RegisteredTechniqueShowsUpWithItsOptions) {
  ASSERT_TRUE(kProbeRegistered);
  const ViewerModel model = makeViewerModel(builtinScene("spheres"), "volume");
  EXPECT_EQ(model.techniques.size(), techniques().size());
  const TechniqueEntry* probe = entryNamed(model, "viewer-test-probe");
  ASSERT_NE(probe, nullptr);
  ASSERT_EQ(probe->options.size(), 4u);
  EXPECT_EQ(probe->options[0].spec->name, "probe-taps");
  EXPECT_EQ(probe->options[0].spec->kind, OptionKind::Integer);
  EXPECT_EQ(probe->options[0].spec->max, 9);
  EXPECT_EQ(probe->options[0].value, "3");
  EXPECT_EQ(probe->options[1].spec->kind, OptionKind::Flag);
  EXPECT_EQ(probe->options[1].value, "false");
  EXPECT_EQ(probe->options[2].spec->kind, OptionKind::Number);
  EXPECT_EQ(probe->options[2].value, "0.25");
  EXPECT_EQ(probe->options[3].spec->choices, (std::vector<std::string>{"near", "far"}));
  EXPECT_EQ(probe->options[3].value, "near");
  // Every built-in technique is listed too, each with its whole table.
  for (const TechniqueInfo& info : techniques()) {
    const TechniqueEntry* entry = entryNamed(model, info.name);
    ASSERT_NE(entry, nullptr) << info.name;
    EXPECT_EQ(entry->options.size(), info.options.specs().size()) << info.name;
  }
}

// Options set through the model reach the technique's config and the command line that
// reproduces the frame; a value the technique refuses leaves the model as it was.
TEST(ViewerModel, OptionsReachTheConfigAndRefusedValuesChangeNothing) {
  ViewerModel model = makeViewerModel(builtinScene("spheres"), "volume");
  selectTechnique(model, "viewer-test-probe");
  const uint64_t before = model.generation;
  setOption(model, "probe-taps", "7");
  setOption(model, "probe-mirror", "true");
  setOption(model, "probe-mode", "far");
  EXPECT_GT(model.generation, before);
  const TechniqueConfig config = techniqueConfig(model);
  EXPECT_EQ(config.name(), "viewer-test-probe");
  EXPECT_EQ(config.options<ProbeOptions>().taps, 7);
  EXPECT_TRUE(config.options<ProbeOptions>().mirror);
  EXPECT_EQ(config.options<ProbeOptions>().mode, ProbeOptions::Mode::Far);
  EXPECT_EQ(renderFlags(model),
            (std::vector<std::string>{"--technique", "viewer-test-probe", "--probe-taps", "7",
                                      "--probe-mirror", "--probe-mode", "far"}));

  const uint64_t generation = model.generation;
  EXPECT_THROW(setOption(model, "probe-taps", "10"), Error);
  EXPECT_THROW(setOption(model, "probe-mode", "middle"), Error);
  EXPECT_THROW(setOption(model, "no-such-option", "1"), Error);
  EXPECT_EQ(techniqueConfig(model).options<ProbeOptions>().taps, 7);
  EXPECT_EQ(model.generation, generation);

  // Switching away and back keeps each technique's values.
  selectTechnique(model, "volume");
  selectTechnique(model, "viewer-test-probe");
  EXPECT_EQ(techniqueConfig(model).options<ProbeOptions>().taps, 7);
  EXPECT_THROW(selectTechnique(model, "no-such-technique"), Error);
}

// The light sliders edit the selected light only and keep it renderable.
TEST(ViewerModel, LightSlidersEditTheSelectedLight) {
  ViewerModel model = makeViewerModel(builtinScene("multilight"), "volume");
  ASSERT_GE(model.lights.size(), 2u);
  const Light first = model.lights[0];
  selectLight(model, 1);
  setLightRadius(model, 0.4f);
  setLightIntensity(model, -1.0f);  // clamped: a negative intensity is no light
  EXPECT_EQ(model.lights[1].radius, 0.4f);
  EXPECT_EQ(model.lights[1].intensity, 0.0f);
  EXPECT_EQ(model.lights[0].radius, first.radius);
  EXPECT_THROW(selectLight(model, model.lights.size()), Error);

  model.lights[0] = rectangleLight(vec3(0, 5, 0), vec3(1, 0, 0), vec3(0, 0, 0.5f));
  selectLight(model, 0);
  setRectangleLight(model, 2.0f, 1.0f, 90.0f);
  EXPECT_NEAR(glm::length(model.lights[0].edge_u), 2.0f, 1e-5f);
  EXPECT_NEAR(glm::length(model.lights[0].edge_v), 1.0f, 1e-5f);
  EXPECT_NO_THROW(checkLightShape(model.lights[0]));
}

TEST(ViewerModel, OverlayAndCompareNamesRoundTrip) {
  for (Overlay overlay : allOverlays()) EXPECT_EQ(parseOverlay(overlayName(overlay)), overlay);
  for (CompareMode mode : allCompareModes()) {
    EXPECT_EQ(parseCompareMode(compareModeName(mode)), mode);
  }
  EXPECT_THROW(parseOverlay("wedges"), Error);
}

// A preview lowers the options that declare a cheaper value (the probe's taps: 2), and only
// where that is cheaper than the value set; the full frame keeps the value set.
TEST(ViewerModel, PreviewTakesTheCheaperOptionValues) {
  ViewerModel model = makeViewerModel(builtinScene("spheres"), "viewer-test-probe");
  std::vector<std::string> changed;
  EXPECT_EQ(previewConfig(model, changed).options<ProbeOptions>().taps, 2);
  EXPECT_EQ(changed, (std::vector<std::string>{"probe-taps 2"}));
  EXPECT_EQ(techniqueConfig(model).options<ProbeOptions>().taps, 3);
  setOption(model, "probe-taps", "1");  // already cheaper than the preview's
  EXPECT_EQ(previewConfig(model, changed).options<ProbeOptions>().taps, 1);
  EXPECT_TRUE(changed.empty());
  // exact declares fewer samples for previews: a technique of the table, not only the probe.
  selectTechnique(model, "exact");
  const int samples = techniqueConfig(model).options<ExactOptions>().samples;
  EXPECT_LT(previewConfig(model, changed).options<ExactOptions>().samples, samples);
  EXPECT_EQ(changed.size(), 1u);
}

// Switching to or from a debug layer renders the frame again (with or without the layers);
// between two ordinary overlays the frame stays.
TEST(ViewerModel, DebugLayerOverlaysRenderAgain) {
  ViewerModel model = makeViewerModel(builtinScene("spheres"), "wedge-3pass");
  const uint64_t start = model.generation;
  setOverlay(model, Overlay::Depth);
  EXPECT_EQ(model.generation, start);
  setOverlay(model, Overlay::WedgeFootprints);
  EXPECT_EQ(model.generation, start + 1);
  EXPECT_EQ(overlayLayer(model.overlay), kWedgeFootprintsLayer);
  setOverlay(model, Overlay::CulledTiles);
  EXPECT_EQ(model.generation, start + 1);
  setOverlay(model, Overlay::Shaded);
  EXPECT_EQ(model.generation, start + 2);
}

}  // namespace test_viewer_model
}  // namespace penumbra::viewer
