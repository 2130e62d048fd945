// Percentage-closer soft shadows (Fernando 2005) on the standard shadow map's depth from the
// light centre (shadows/shadowmap/: a cube, or a spot fitted around the visible points), with
// the sphere light's radius as the light size, so its images compare with the wedges', the
// exact volumes' and the oracle's. Per visible point (pcss_filter.h): a blocker search over the
// part of the map through which the light's sphere can be hidden, the average blocker distance,
// the penumbra width it gives by similar triangles, and percentage-closer filtering over that
// width. Approximate: it assumes every blocker in the search region is at their average
// distance and that the blockers are planar and parallel to the light (the paper's own
// assumptions), and a single depth map from the centre cannot see what only the light's rim
// sees. At radius 0 it is the plain shadow map (one lookup), not the exact hard shadow.
// Beyond the paper (PcssOptions): the answer is scaled by the share of the light above the
// receiver's own plane (aboveHorizon in pcss_filter.h), and `--occluder-test plane` replaces
// the depth bias with the receiver-plane test (ReceiverPlane in shadow_map_lookup.h).
//
// The lookups run a row's points face by face through the PCSS kernel (pcss_kernel.h), SIMD
// over points, or its scalar twin (RenderContext::simd).
//
// Counters: the map's rasterization counts its own; z_reads adds every map read of the
// lookups; shadow_map_lookups counts the pixels looked up.
#include "shadows/pcss/pcss_technique.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/timer.h"
#include "shadows/pcss/pcss_filter.h"
#include "shadows/pcss/pcss_kernel.h"
#include "shadows/stages/light_depth_maps/light_depth_maps.h"
#include "shadows/stages/light_depth_maps/light_frustum.h"
#include "shadows/stages/light_depth_maps/lookup_counters.h"
#include "shadows/stages/light_depth_maps/shadow_map_lookup.h"

namespace penumbra {
namespace {

constexpr double kTwoPi = 6.283185307179586;

class Pcss final : public PreparedTechnique {
 public:
  Pcss(const PcssOptions& options, const Scene& scene)
      : options_(options), scene_(scene), triangles_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    // Its blocker search and filter widths come from a sphere's radius (Fernando 2005).
    requireSphereLight(light, "pcss");
    TechniqueResult result;
    Stats& stats = result.stats;
    const LightDepthMaps maps = drawLightDepthMaps(
        scene_, triangles_, light,
        chooseLightFrustums(scene_, light, view, eye, options_.projection, 0.0),
        options_.resolution, stats, context.simd);
    const std::vector<double> nearest = nearestOccluders(maps);

    PassTimer timer(stats, "lookups");
    const VogelSpiral blocker_spiral(options_.blocker_samples);
    const VogelSpiral filter_spiral(options_.filter_samples);
    PcssShape shape;
    shape.light_radius = double(light.radius);
    shape.constant_bias = options_.constant_bias;
    shape.plane_test = options_.occluder_test == PcssOccluderTest::Plane;
    shape.blocker = &blocker_spiral;
    shape.filter = &filter_spiral;
    std::vector<uint64_t> reads(size_t(view.height), 0);
    lookupVisiblePoints(
        scene_, light, view, eye, maps, nullptr, options_.normal_offset, result.visibility, stats,
        [&](const LookupBatch& batch, float* values) {
          const size_t n = batch.padded();
          std::vector<double> texel(n), slope_bias(n), turn_cos(n, 1.0), turn_sin(n, 0.0);
          for (size_t k = 0; k < n; ++k) {
            texel[k] = maps.texelSize(batch.face, batch.w[k]);
            slope_bias[k] = options_.slope_bias * batch.slope[k];
          }
          for (size_t k = 0; k < batch.count(); ++k) {
            const double turn = kTwoPi * pixelRotation(batch.x[k], batch.y);
            turn_cos[k] = std::cos(turn);
            turn_sin[k] = std::sin(turn);
          }
          PcssFace face;
          face.texels = {maps.depth[size_t(batch.face)].data(), maps.size, maps.near};
          face.nearest = nearest[size_t(batch.face)];
          face.texels_per_tangent = maps.size / (2.0 * maps.tan_half[size_t(batch.face)]);
          const PcssPoints points{batch.sx.data(),      batch.sy.data(),      batch.w.data(),
                                  texel.data(),         slope_bias.data(),    turn_cos.data(),
                                  turn_sin.data(),      batch.plane_a.data(), batch.plane_x.data(),
                                  batch.plane_y.data()};
          pcssVisibility(face, shape, points, values, n, reads[size_t(batch.y)], context.simd);
          if (options_.horizon) {
            for (size_t k = 0; k < batch.count(); ++k)
              values[k] *= float(aboveHorizon(batch.light_height[k], light.radius));
          }
        });
    for (const uint64_t n : reads) stats.z_reads += n;
    return result;
  }

 private:
  PcssOptions options_;
  const Scene& scene_;
  SceneTriangles triangles_;
};

}  // namespace

TechniqueInfo pcssTechnique() {
  TechniqueInfo info;
  info.name = "pcss";
  info.summary =
      "percentage-closer soft shadows (Fernando 2005): blocker search, penumbra estimate from "
      "the sphere light's radius, variable-size PCF on a shadow map";
  info.traits.soft = true;
  // At radius 0 PCSS is the plain shadow map: its boundary moves by up to a texel, so it cannot
  // equal the hard volume bit for bit; held instead to a mean difference from it over covered
  // pixels (TechniqueTraits::zero_radius_mae_bound).
  // Measured at the conformance suite's 160 x 107 (1024 texels, 16 + 32 samples, auto
  // projection): against the volume at radius 0, with slope bias 1, spheres 0.0007, columns
  // 0.0032, multilight 0.0004; against the 1024-ray oracle with the defaults (slope bias 1.5,
  // the horizon), covered pixels: spheres 0.0011, columns 0.0196, fractal 0.0043 (penumbra
  // 0.029), year2002 0.0080. The bounds leave half again of the largest.
  info.traits.zero_radius_mae_bound = 0.005;
  info.traits.covered_mae_bound = 0.03;
  info.counters = {kShadowMapLookups, kLookupsSaved};
  info.traits.penumbra_mae_bound = 0.18;
  info.options =
      OptionTableBuilder<PcssOptions>()
          .integer("shadow-map-size", "texels along each side of each face (six for a cube)",
                   &PcssOptions::resolution, 16, 4096)
          .choice("projection",
                  "auto (a spot fitted around the visible points when the light is outside "
                  "them, else a cube), cube (six faces) or spot (one frustum)",
                  &PcssOptions::projection,
                  {{"auto", ShadowMapProjection::Auto},
                   {"cube", ShadowMapProjection::Cube},
                   {"spot", ShadowMapProjection::Spot}})
          .number("constant-bias", "depth bias in texels at the receiver's distance",
                  &PcssOptions::constant_bias, 0.0, 1000.0)
          .number("slope-bias",
                  "slope-scaled depth bias: x tan(normal, light direction) x each lookup's "
                  "distance in texels",
                  &PcssOptions::slope_bias, 0.0, 1000.0)
          .number("normal-offset",
                  "normal-offset sampling: the point is looked up this many texels off its "
                  "surface, along its normal",
                  &PcssOptions::normal_offset, 0.0, 1000.0)
          .choice("occluder-test",
                  "which samples occlude, in the blocker search and the filter: plane (those "
                  "whose surface point lies more than constant-bias texels above the receiver's "
                  "plane) or depth (those in front of the receiver less the constant and slope "
                  "biases, Fernando 2005)",
                  &PcssOptions::occluder_test,
                  {{"depth", PcssOccluderTest::Depth}, {"plane", PcssOccluderTest::Plane}})
          .flag("no-horizon",
                "leave out the receiver's own horizon (the share of the light below the plane "
                "of the visible triangle, which the filter does not see)",
                &PcssOptions::horizon, false)
          .integer("blocker-samples", "lookups of the blocker search (a turned spiral)",
                   &PcssOptions::blocker_samples, 1, 256)
          .integer("filter-samples", "lookups of the percentage-closer filter (a turned spiral)",
                   &PcssOptions::filter_samples, 1, 1024)
          .describe([](const PcssOptions& o) {
            static const char* kProjection[] = {"auto", "cube", "spot"};
            static const char* kOccluderTest[] = {"depth", "plane"};
            return fmt::format(
                "{}^2, {}, {} blocker + {} filter samples, bias {} + {} slope, normal offset {}, "
                "{} occluder test",
                o.resolution, kProjection[int(o.projection)], o.blocker_samples, o.filter_samples,
                formatNumber(o.constant_bias), formatNumber(o.slope_bias),
                formatNumber(o.normal_offset),
                kOccluderTest[int(o.occluder_test)]);
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<Pcss>(std::any_cast<const PcssOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
