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

#include "core/timer.h"
#include "raster/rasterizer.h"
#include "shadows/facing_away.h"

namespace penumbra {
namespace {

// Side quads of every silhouette edge, extruded from the light centre to infinity, and with
// z-fail the caps. Payloads are signed weights of polygons facing out of the volume
// (rasterizer.h, rasterizeStencil).
void appendVolumePolygons(const Mesh& mesh, const vec3& centre, const View& view,
                          CasterVolume& volume, ClipTriangles& out) {
  appendExtrudedVertices(mesh, centre, view, volume, out);
  const uint32_t finite = volume.finite, infinite = volume.infinite;
  const uint8_t flags = volume.zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : volume.silhouette.edges) {
    // Quad (v1, v0, v0', v1') as two triangles sharing the diagonal v1-v0'.
    out.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
    out.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
  }
  // z-pass: caps are never in front of a visible point (see above).
  if (!volume.zfail) return;
  forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
    out.add(a, b, c, weight, flags);
  });
}

class ShadowVolumes final : public PreparedTechnique {
 public:
  ShadowVolumes(const VolumeOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    TechniqueResult result;
    Stats& stats = result.stats;
    ClipTriangles polygons(eye.clip_vertices);
    {
      PassTimer timer(stats, "silhouette");
      for (size_t m = 0; m < scene_.meshes.size(); ++m) {
        CasterVolume volume = casterVolume(scene_, m, eye, light.center, view, options_.mode,
                                           CasterPolicy::Auto);
        stats.silhouette_edges += volume.silhouette.edges.size();
        appendVolumePolygons(scene_.meshes[m], light.center, view, volume, polygons);
      }
    }
    Image<int32_t> stencil(view.width, view.height, 0);
    {
      PassTimer timer(stats, "volumes");
      StencilOptions stencil_options;
      stencil_options.simd = context.simd;
      stencil_options.two_level = options_.two_level_stencil;
      rasterizeStencil(polygons, eye.depth, stencil, stats, stencil_options);
    }
    {
      PassTimer timer(stats, "resolve");
      resolveVisibility(scene_, light, view, eye, result.visibility,
                        [&](int x, int y) { return stencil.at(x, y) != 0 ? 0.0f : 1.0f; });
    }
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
  info.summary = "hard shadow volumes from the light centre, z-pass / z-fail per caster";
  // Ties only: pixels whose point lies on a volume polygon, at most a few per frame.
  info.traits.covered_mae_bound = 0.001;
  info.options =
      OptionTableBuilder<VolumeOptions>()
          .choice("volume-mode", "count from the eye (zpass), from infinity (zfail), or auto",
                  &VolumeOptions::mode,
                  {{"auto", VolumeMode::Auto}, {"zpass", VolumeMode::ZPass},
                   {"zfail", VolumeMode::ZFail}})
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
