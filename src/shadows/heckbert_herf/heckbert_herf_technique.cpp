// Heckbert-Herf: visibility = (1 / N) sum over N light points q_k of the hard shadow volume's
// 0 / 1 answer for a point light at q_k (shadow_stencil.h, hardShadowVolumes, which also
// shadows the points whose triangle faces away from q_k). Each pixel's count of lit renders is
// an integer, so the average does not depend on the order the renders finish in. It converges
// to the fraction of the light's area a point sees as N grows (stratified: error falls at least
// like N^-1/2), which is the oracle's answer up to the oracle's own noise; a sphere light is
// represented by the disk facing the scene (light_points.h), where the oracle samples the cap
// each point sees.
#include "shadows/heckbert_herf/heckbert_herf_technique.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/parallel.h"
#include "core/timer.h"
#include "shadows/heckbert_herf/light_points.h"
#include "shadows/shared_options.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace {

constexpr int kMinLightPoints = 4, kMaxLightPoints = 1024;

class HeckbertHerf final : public PreparedTechnique {
 public:
  HeckbertHerf(const HeckbertHerfOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    checkLightShape(light);
    ShadowStencilOptions stencil_options;
    stencil_options.simd = context.simd;
    // Culled once for the whole light: a caster no segment from a visible point to the light
    // meets casts nothing from any of its points.
    Stats culling_stats;
    const CasterCulling culling =
        cullCasters(scene_, light, view, eye, context.caster_culling, culling_stats);
    stencil_options.caster_culling = &culling;
    // A point light: one render, the hard shadow volume's image exactly.
    if (!(light.radius > 0.0f)) {
      TechniqueResult hard =
          hardShadowVolumes(scene_, light, view, eye, stencil_options, context.debug_layers);
      putCullingFirst(std::move(culling_stats), hard.stats);
      return hard;
    }
    const std::vector<vec3> points =
        heckbertHerfPoints(light, options_.samples, options_.seed, scene_.bounds().center());
    TechniqueResult result;
    result.stats = std::move(culling_stats);
    const int width = view.width, height = view.height;
    std::vector<uint16_t> lit(size_t(width) * size_t(height), 0);
    Light point = light;
    point.shape = LightShape::Sphere;
    point.radius = 0.0f;
    point.texture = nullptr;
    // A textured light (light.h): each render weighs, per channel, the texel its point is on;
    // the weighted sums run in the points' order, whatever the threads.
    const bool textured = light.texture != nullptr;
    ChannelVisibility weighted;
    dvec3 total_weight(0.0);
    if (textured) {
      for (Image<float>& c : weighted) c.resize(width, height, 0.0f);
    }
    const dvec3 u(light.edge_u), v(light.edge_v);
    for (const vec3& q : points) {
      point.center = q;
      TechniqueResult hard = hardShadowVolumes(scene_, point, view, eye, stencil_options);
      result.stats.addCounters(hard.stats);
      PassTimer timer(result.stats, "average");
      vec3 weight(0.0f);
      if (textured) {
        const dvec3 d = dvec3(q) - dvec3(light.center);
        weight = light.texture->at(vec2(float(glm::dot(d, u) / glm::dot(u, u) + 0.5),
                                        float(glm::dot(d, v) / glm::dot(v, v) + 0.5)));
        total_weight += dvec3(weight);
      }
      parallelFor(size_t(height), [&](size_t y) {
        const float* vis = hard.visibility.row(int(y));
        uint16_t* row = lit.data() + y * size_t(width);
        for (int x = 0; x < width; ++x) row[x] = uint16_t(row[x] + (vis[x] > 0.5f ? 1 : 0));
        if (!textured) return;
        for (int c = 0; c < 3; ++c) {
          float* out = weighted[size_t(c)].row(int(y));
          for (int x = 0; x < width; ++x) out[x] += vis[x] > 0.5f ? weight[c] : 0.0f;
        }
      });
    }
    PassTimer timer(result.stats, "resolve");
    result.visibility.resizeForOverwrite(width, height);
    const float scale = 1.0f / float(points.size());
    parallelFor(size_t(height), [&](size_t y) {
      const uint16_t* row = lit.data() + y * size_t(width);
      float* out = result.visibility.row(int(y));
      for (int x = 0; x < width; ++x) out[x] = float(row[x]) * scale;
    });
    if (textured) {
      for (int c = 0; c < 3; ++c) {
        // A channel the points never saw lit emits nothing there: it counts as visible.
        const float inv = total_weight[c] > 0.0 ? float(1.0 / total_weight[c]) : 0.0f;
        Image<float>& channel = weighted[size_t(c)];
        for (size_t i = 0; i < channel.size(); ++i) {
          channel[i] = inv > 0.0f ? std::min(1.0f, channel[i] * inv) : 1.0f;
        }
      }
      setChannelVisibility(result, light, std::move(weighted));
    }
    return result;
  }

 private:
  HeckbertHerfOptions options_;
  const Scene& scene_;
};

}  // namespace

TechniqueInfo heckbertHerfTechnique() {
  TechniqueInfo info;
  info.name = "heckbert-herf";
  info.counters = casterCullingCounters();
  info.aliases = {"hh"};
  info.summary = "Heckbert-Herf 1997: the average of N hard shadow volumes from stratified "
                 "points on the light (sphere, disk or rectangle)";
  info.traits.soft = true;
  // Against the 1024-ray oracle at the conformance size with 16 samples: covered
  // 0.0013-0.0097, penumbra 0.038-0.046 (the banding of 16 hard shadows, and the sphere taken
  // as the disk facing the scene). Bounds: about 1.5x and 2x.
  info.traits.covered_mae_bound = 0.015;
  info.traits.penumbra_mae_bound = 0.08;
  OptionTableBuilder<HeckbertHerfOptions> table;
  samplesOption(table, "hard shadow renders averaged, one per stratified light point",
                &HeckbertHerfOptions::samples, kMinLightPoints, kMaxLightPoints);
  info.options =
      seedOption(table, "the jitter inside the light's strata", &HeckbertHerfOptions::seed)
          .describe([](const HeckbertHerfOptions& o) {
            return fmt::format("{} samples, seed {}", o.samples, o.seed);
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<HeckbertHerf>(std::any_cast<const HeckbertHerfOptions&>(options),
                                          scene);
  };
  return info;
}

}  // namespace penumbra
