// Renders the built-in `spheres` scene with hard shadow volumes and with penumbra wedges through
// the installed package's public headers only, and checks the frames are sane. Exit code 0 when
// they are.
#include <penumbra/penumbra.h>

#include <cstdio>
#include <exception>

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "FAILED: %s\n", what);
  ++failures;
}

// Visibility in [0, 1] everywhere, some pixels in shadow and some lit.
void checkFrame(const char* name, const penumbra::Scene& scene,
                const penumbra::FrameResult& frame) {
  std::printf("%s: %zu lights, %.2f ms\n", name, frame.lights.size(), frame.total.totalMs());
  expect(frame.lights.size() == scene.lights.size(), "one visibility buffer per light");
  expect(frame.color.width() == 64 && frame.color.height() == 48, "colour image of 64x48");
  for (const penumbra::TechniqueResult& light : frame.lights) {
    const penumbra::Image<float>& v = light.visibility;
    expect(v.width() == 64 && v.height() == 48, "visibility of 64x48");
    size_t shadowed = 0, lit = 0, out_of_range = 0;
    for (size_t i = 0; i < v.size(); ++i) {
      if (!(v[i] >= 0.0f && v[i] <= 1.0f)) ++out_of_range;
      if (v[i] < 0.5f) ++shadowed;
      if (v[i] == 1.0f) ++lit;
    }
    std::printf("  %zu pixels shadowed, %zu lit, %zu outside [0, 1]\n", shadowed, lit,
                out_of_range);
    expect(out_of_range == 0, "visibility in [0, 1]");
    expect(shadowed > 0, "some pixels in shadow");
    expect(lit > 0, "some pixels lit");
    expect(light.stats.pixels_rasterized > 0, "the technique rasterized something");
  }
}

}  // namespace

int main() {
  try {
    const penumbra::Scene scene = penumbra::loadScene("spheres");

    // Hard shadow volumes, options given as the technique's own struct.
    penumbra::FrameOptions hard;
    hard.width = 64;
    hard.height = 48;
    penumbra::VolumeOptions volume;
    volume.mode = penumbra::VolumeMode::ZFail;
    hard.technique = penumbra::TechniqueConfig("volume", volume);
    const penumbra::FrameResult hard_frame = penumbra::renderFrame(scene, hard);
    checkFrame("volume", scene, hard_frame);

    // Penumbra wedges, typed access to the default options; a renderer prepared once.
    penumbra::FrameOptions soft;
    soft.width = 64;
    soft.height = 48;
    soft.technique = penumbra::TechniqueConfig("wedge-3pass");
    soft.technique.options<penumbra::WedgeOptions>().cull = penumbra::CullMode::ZMax;
    soft.technique.options<penumbra::WedgeOptions>().tile_level = 3;
    const penumbra::FrameRenderer renderer(scene, soft);
    penumbra::FrameResult soft_frame;
    renderer.render(soft_frame);
    checkFrame(soft.technique.describe().c_str(), scene, soft_frame);

    // Soft and hard shadows agree away from the penumbrae.
    const penumbra::ImageDifference d = penumbra::compareImages(
        soft_frame.lights[0].visibility, hard_frame.lights[0].visibility, 0.5);
    std::printf("wedges against volumes: mean error %.4f, %.1f %% of pixels off by > 0.5\n",
                d.mae, 100.0 * d.fraction_over_tolerance);
    expect(d.mae < 0.25, "wedges close to the hard shadow on average");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "FAILED: %s\n", e.what());
    return 1;
  }
  if (failures > 0) return 1;
  std::printf("ok\n");
  return 0;
}
