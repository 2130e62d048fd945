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
//
// The lookup loop is scalar in this version (RenderContext::simd reaches the rasterizer only).
//
// Counters: the map's rasterization counts its own; z_reads adds every map read of the
// lookups; shadow_map_lookups counts the pixels looked up.
#include "shadows/pcss/pcss_technique.h"

#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/timer.h"
#include "shadows/pcss/pcss_filter.h"
#include "shadows/shadowmap/light_depth_maps.h"
#include "shadows/shadowmap/light_frustum.h"
#include "shadows/shadowmap/shadow_map_lookup.h"

namespace penumbra {
namespace {

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
    PcssSettings settings;
    settings.radius = double(light.radius);
    settings.constant_bias = options_.constant_bias;
    settings.slope_bias = options_.slope_bias;
    settings.blocker_samples = options_.blocker_samples;
    settings.filter_samples = options_.filter_samples;
    std::vector<uint64_t> reads(size_t(view.height), 0);
    lookupVisiblePoints(scene_, light, view, eye, maps, nullptr, result.visibility, stats,
                        [&](int x, int y, const dvec3&, const MapPoint& m, double slope) {
                          return pcssVisibility(maps, m, slope, pixelRotation(x, y), settings,
                                                reads[size_t(y)], nearest[size_t(m.face)]);
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
  // Measured with the defaults (1024 texels, 16 + 32 samples, auto projection) at the
  // conformance suite's 160 x 107, against the volume at radius 0: spheres 0.0007, columns
  // 0.0032, multilight 0.0004; against the 1024-ray oracle, covered / penumbra pixels: spheres
  // 0.0039 / 0.119, columns 0.0200 / 0.059, fractal 0.0083 / 0.062, year2002 0.0083 / 0.049,
  // multilight 0.0026 / 0.074. The bounds leave half again of the largest.
  info.traits.zero_radius_mae_bound = 0.005;
  info.traits.covered_mae_bound = 0.03;
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
          .integer("blocker-samples", "lookups of the blocker search (a turned spiral)",
                   &PcssOptions::blocker_samples, 1, 256)
          .integer("filter-samples", "lookups of the percentage-closer filter (a turned spiral)",
                   &PcssOptions::filter_samples, 1, 1024)
          .describe([](const PcssOptions& o) {
            static const char* kProjection[] = {"auto", "cube", "spot"};
            return fmt::format("{}^2, {}, {} blocker + {} filter samples, bias {} + {} slope",
                               o.resolution, kProjection[int(o.projection)], o.blocker_samples,
                               o.filter_samples, formatNumber(o.constant_bias),
                               formatNumber(o.slope_bias));
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<Pcss>(std::any_cast<const PcssOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
