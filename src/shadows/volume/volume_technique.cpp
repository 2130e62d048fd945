// Hard shadow volumes (Crow 1977) counted in an integer stencil buffer: z-pass (Heidmann 1991)
// or z-fail (Everitt & Kilgard 2002), as reviewed in the 2004 paper, sections 2 and 5, and in
// the 2005 thesis, section 2.2.
//
// z-pass counts volume polygons strictly in front of the visible point, front faces +, back
// faces -; it needs no caps because a light cap in front of the point would be an opaque
// triangle hiding it, and dark caps lie at infinity. z-fail counts polygons behind the point or
// at its depth, back faces +, front faces -, caps included. A light cap coinciding with the
// visible surface (bit-identical depth, caster_volume.h) is thus counted by z-fail, which is
// what makes a point on a triangle's unlit side come out shadowed. With the eye outside every
// volume both counts are equal, since each closed volume's polygons sum to zero along a ray.
#include "shadows/volume/volume_technique.h"

#include <utility>

#include "shadows/shared_options.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace {

class ShadowVolumes final : public PreparedTechnique {
 public:
  ShadowVolumes(const VolumeOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    ShadowStencilOptions stencil_options;
    stencil_options.mode = options_.mode;
    stencil_options.two_level_stencil = options_.two_level_stencil;
    stencil_options.simd = context.simd;
    Stats culling_stats;
    const CasterCulling culling =
        cullCasters(scene_, light, view, eye, context.caster_culling, culling_stats);
    stencil_options.caster_culling = &culling;
    TechniqueResult result =
        hardShadowVolumes(scene_, light, view, eye, stencil_options, context.debug_layers);
    putCullingFirst(std::move(culling_stats), result.stats);
    return result;
  }

 private:
  VolumeOptions options_;
  const Scene& scene_;
};

}  // namespace

TechniqueInfo volumeTechnique() {
  TechniqueInfo info;
  info.name = "volume";
  info.counters = casterCullingCounters();
  info.summary = "hard shadow volumes from the light centre, z-pass / z-fail per caster";
  // Ties only: pixels whose point lies on a volume polygon, at most a few per frame.
  info.traits.covered_mae_bound = 0.001;
  OptionTableBuilder<VolumeOptions> table;
  info.options =
      volumeModeOption(table, &VolumeOptions::mode)
          .flag("one-level-stencil",
                "every volume pixel depth-tested and written, as the papers' passes (otherwise "
                "tiles a polygon covers and passes whole take one coarse stencil write)",
                &VolumeOptions::two_level_stencil, false)
          .describe([](const VolumeOptions& o) {
            return volumeModeName(o.mode) + (o.two_level_stencil ? "" : ", one-level stencil");
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<ShadowVolumes>(std::any_cast<const VolumeOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
