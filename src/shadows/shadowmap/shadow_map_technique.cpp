// The standard shadow map (Williams 1978), as reviewed in Aila's 2005 thesis, section 2.3.
//
// The light's depth is drawn through a cube of six 90-degree faces around the light centre, or
// one spot frustum fitted around the view's visible points when the light is outside them
// (light_frustum.h: --projection auto picks), or a spotlight's frustum (--spot-fov), with the
// eye pass's rasterizer (light_depth_maps.h). Per pixel of the eye buffers the visible point p
// is moved off its surface along its normal (normal-offset sampling, shadow_map_lookup.h) and
// projected into its face, and an N x N kernel of stored depths around the projected position
// is compared with p's distance along the face's axis, less a bias (growing with each tap's
// distance from the kernel's centre by the ring bias, map_lookup_kernel.h); visibility is the
// fraction of lookups that find no occluder in front (percentage-closer filtering, Reeves,
// Salesin & Cook 1987). With --stencil-limit, the spot's frustum is first rasterized as a volume
// into a stencil and only the pixels inside it are looked up (Arvo & Aila 2003; thesis
// section 4.2).
//
// The lookups run a row's points face by face through the PCF kernel (map_lookup_kernel.h),
// SIMD over points, or its scalar twin (RenderContext::simd).
//
// Counters: the faces' rasterization counts its own (pixels_rasterized, z_reads,
// stencil_writes as depth writes, triangles), so does the frustum's stencil; the lookups add
// N x N depth-buffer reads per looked-up pixel to z_reads, and shadow_map_lookups and
// lookups_saved count the pixels looked up and skipped.
#include "shadows/shadowmap/shadow_map_technique.h"

#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/timer.h"
#include "shadows/shadowmap/light_frustum_stencil.h"
#include "shadows/stages/light_depth_maps/light_depth_maps.h"
#include "shadows/stages/light_depth_maps/light_frustum.h"
#include "shadows/stages/light_depth_maps/lookup_counters.h"
#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"
#include "shadows/stages/light_depth_maps/shadow_map_lookup.h"

namespace penumbra {
namespace {

class ShadowMap final : public PreparedTechnique {
 public:
  ShadowMap(const ShadowMapOptions& options, const Scene& scene)
      : options_(options), scene_(scene), triangles_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    requireSphereLight(light, "shadow-map");
    TechniqueResult result;
    Stats& stats = result.stats;
    LightFrustums frustums = chooseLightFrustums(scene_, light, view, eye, options_.projection,
                                                 options_.spot_fov);
    std::optional<Image<int32_t>> limit;
    if (options_.stencil_limit && !frustums.cube())
      limit = lightFrustumStencil(light, frustums.faces[0], view, eye, stats, context.simd);
    const LightDepthMaps maps = drawLightDepthMaps(scene_, triangles_, light, std::move(frustums),
                                                   options_.resolution, stats, context.simd);

    PassTimer timer(stats, "lookups");
    const int kernel = options_.pcf_kernel;
    const double reach = 0.5 * double(kernel + 1);  // texels from p to the farthest lookup
    lookupVisiblePoints(
        scene_, light, view, eye, maps, limit ? &*limit : nullptr, options_.normal_offset * reach,
        result.visibility, stats,
        [&](const LookupBatch& batch, float* values) {
          std::vector<double> receiver(batch.padded()), ring_bias(batch.padded());
          for (size_t k = 0; k < batch.padded(); ++k) {
            // Bias, in world units along the axis, from the texel's world size at p's distance;
            // the ring bias grows with each tap's distance from the kernel's centre.
            const double bias =
                maps.texelSize(batch.face, batch.w[k]) *
                (options_.constant_bias + options_.slope_bias * batch.slope[k] * reach);
            receiver[k] = batch.w[k] - bias;
            ring_bias[k] = maps.texelSize(batch.face, batch.w[k]) * options_.ring_bias;
          }
          const FaceTexels face{maps.depth[size_t(batch.face)].data(), maps.size, maps.near};
          pcfVisibility(face, batch.sx.data(), batch.sy.data(), receiver.data(), ring_bias.data(),
                        kernel, values,
                        batch.padded(), context.simd);
        });
    stats.z_reads += stats.counter(kShadowMapLookups.name) * uint64_t(kernel) * uint64_t(kernel);
    return result;
  }

 private:
  ShadowMapOptions options_;
  const Scene& scene_;
  SceneTriangles triangles_;
};

}  // namespace

TechniqueInfo shadowMapTechnique() {
  TechniqueInfo info;
  info.name = "shadow-map";
  info.summary =
      "standard shadow map: cube map or spot frustum of depth from the light centre, bias, PCF, "
      "stencil-limited lookups";
  // Hard, approximate: the shadow boundary moves by up to a texel (PCF blurs it over the kernel)
  // and the bias and normal offset light a thin band at contact. Measured with the defaults
  // (1024 texels, 3 x 3 PCF, normal offset 0.8, ring bias 4, auto projection) against the
  // one-ray oracle at the conformance suite's 160 x 107: MAE over covered pixels spheres
  // 0.0015, columns 0.0109, fractal 0.0068, year2002 0.0055; the bound leaves a third again of
  // the largest.
  info.traits.covered_mae_bound = 0.015;
  info.counters = {kShadowMapLookups, kLookupsSaved};
  info.options =
      OptionTableBuilder<ShadowMapOptions>()
          .integer("shadow-map-size", "texels along each side of each face (six for a cube)",
                   &ShadowMapOptions::resolution, 16, 4096)
          .integer("pcf-kernel",
                   "percentage-closer filtering over N x N lookups, N odd (1: plain shadow map)",
                   &ShadowMapOptions::pcf_kernel, 1, 15)
          .number("constant-bias", "depth bias in texels at the receiver's distance",
                  &ShadowMapOptions::constant_bias, 0.0, 1000.0)
          .number("slope-bias",
                  "slope-scaled depth bias: x tan(normal, light direction) x the kernel's reach "
                  "in texels",
                  &ShadowMapOptions::slope_bias, 0.0, 1000.0)
          .number("normal-offset",
                  "normal-offset sampling: the point is looked up this many times the kernel's "
                  "reach in texels off its surface, along its normal",
                  &ShadowMapOptions::normal_offset, 0.0, 100.0)
          .number("ring-bias",
                  "extra depth bias in texels per texel a PCF tap lies from the kernel's centre "
                  "(ring), for receivers that are not planar",
                  &ShadowMapOptions::ring_bias, 0.0, 1000.0)
          .choice("projection",
                  "auto (a spot fitted around the visible points when the light is outside "
                  "them, else a cube), cube (six faces) or spot (one frustum)",
                  &ShadowMapOptions::projection,
                  {{"auto", ShadowMapProjection::Auto},
                   {"cube", ShadowMapProjection::Cube},
                   {"spot", ShadowMapProjection::Spot}})
          .number("spot-fov",
                  "0: the spot is fitted around the visible points; else the light is a "
                  "spotlight of this full angle in degrees, aimed at the scene's centre, dark "
                  "outside",
                  &ShadowMapOptions::spot_fov, 0.0, 170.0)
          .flag("stencil-limit",
                "look up only pixels inside the spot's frustum, found by drawing it as a volume "
                "into a stencil (Arvo & Aila 2003)",
                &ShadowMapOptions::stencil_limit)
          .check([](const ShadowMapOptions& o) {
            PENUMBRA_CHECK(o.pcf_kernel % 2 == 1,
                           "shadow-map: --pcf-kernel {} must be odd (a kernel centred on the "
                           "texel the point projects to)",
                           o.pcf_kernel);
            PENUMBRA_CHECK(!(o.spot_fov > 0.0 && o.projection == ShadowMapProjection::Cube),
                           "shadow-map: --spot-fov {} makes the light a spotlight, which needs "
                           "--projection spot or auto, not cube",
                           formatNumber(o.spot_fov));
            PENUMBRA_CHECK(!(o.stencil_limit && o.projection == ShadowMapProjection::Cube),
                           "shadow-map: --stencil-limit needs a spot frustum (--projection spot "
                           "or auto), not cube");
          })
          .describe([](const ShadowMapOptions& o) {
            static const char* kProjection[] = {"auto", "cube", "spot"};
            std::string text = fmt::format(
                "{}^2, {}, pcf {}x{}, bias {} + {} slope + {} per ring, normal offset {}",
                o.resolution, kProjection[int(o.projection)], o.pcf_kernel, o.pcf_kernel,
                formatNumber(o.constant_bias), formatNumber(o.slope_bias),
                formatNumber(o.ring_bias), formatNumber(o.normal_offset));
            if (o.spot_fov > 0.0)
              text += fmt::format(", spotlight {} deg", formatNumber(o.spot_fov));
            if (o.stencil_limit) text += ", stencil-limited";
            return text;
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<ShadowMap>(std::any_cast<const ShadowMapOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
