#include "shadows/reference/reference_technique.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/timer.h"
#include "shadows/reference/embree_scene.h"
#include "shadows/shared_options.h"
#include "shadows/stages/light_sampling/light_sampling.h"
#include "shadows/stages/light_sampling/ray_origin.h"

namespace penumbra {
namespace {

constexpr int kMaxRays = 4096;

// Shortens every shadow ray by this relative amount so the point the ray aims at (the light's
// centre or a point on its surface) never counts as an occluder of itself.
constexpr double kTfarShrink = 1e-6;

ShadowRay makeRay(const vec3& origin, const vec3& direction_unit, double distance) {
  ShadowRay ray;
  ray.origin = origin;
  ray.direction = direction_unit;
  ray.tfar = float(distance * (1.0 - kTfarShrink));
  return ray;
}

struct RowCounters {
  uint64_t z_reads = 0;
  uint64_t rays = 0;
};

// The scene's BVH is built once, when the technique is prepared for the scene; every light and
// frame traces against it.
class Oracle final : public PreparedTechnique {
 public:
  Oracle(const ReferenceOptions& options, const Scene& scene)
      : options_(options), scene_(scene), bvh_(scene) {}
  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  ReferenceOptions options_;
  const Scene& scene_;
  EmbreeScene bvh_;
};

// One render's rows of shadow rays: everything a row's work shares. One work item per row.
class OracleRows {
 public:
  OracleRows(const Light& light, const ReferenceOptions& options, const EmbreeScene& bvh,
             const RayOrigins& origins, const EyeBuffers& eye, bool simd, bool hard,
             Image<float>& visibility, ChannelVisibility& channels)
      : light_(light), options_(options), bvh_(bvh), origins_(origins), eye_(eye),
        visibility_(visibility), channels_(channels), simd_(simd),
        n_(hard ? 1 : options.rays), center_(light.center), radius_(light.radius),
        planar_(light.shape != LightShape::Sphere),
        textured_(!hard && light.texture != nullptr) {}

  // One ray per pixel to the light centre; a row's rays converge on it, so they make coherent
  // packets.
  void traceHardRow(int y, RowCounters& counters) const {
    const float* depth = eye_.depth.depth.row(y);
    const uint32_t* primitive = eye_.primitive.empty() ? nullptr : eye_.primitive.row(y);
    float* visibility = visibility_.row(y);
    std::vector<ShadowRay> rays;
    std::vector<uint8_t> blocked;
    OriginTriangle triangle;  // the row's last visible triangle (RayOrigins::start)
    std::vector<int> columns;
    for (int x = 0; x < eye_.depth.width(); ++x) {
      if (!(depth[x] > 0.0f)) continue;  // background (depth 0) stays fully lit
      ++counters.z_reads;
      const RayStart start =
          origins_.start(x, y, depth[x], primitive ? primitive[x] : kNoPrimitive, triangle);
      const dvec3 to_light = center_ - start.origin;
      const double distance = glm::length(to_light);
      if (distance == 0.0) continue;  // the light sits on the point: nothing in between
      ++counters.rays;
      if (start.intoSurface(center_)) {
        visibility[x] = 0.0f;
        continue;
      }
      rays.push_back(makeRay(vec3(start.origin), vec3(to_light / distance), distance));
      columns.push_back(x);
    }
    blocked.resize(rays.size());
    bvh_.occluded(rays.data(), rays.size(), simd_, blocked.data());
    for (size_t i = 0; i < rays.size(); ++i) visibility[columns[i]] = blocked[i] ? 0.0f : 1.0f;
  }

  // n rays per pixel over the light; visibility is the fraction not blocked (per channel, the
  // texture-weighted fraction, for a textured light).
  void traceSoftRow(int y, RowCounters& counters) const {
    const float* depth = eye_.depth.depth.row(y);
    const uint32_t* primitive = eye_.primitive.empty() ? nullptr : eye_.primitive.row(y);
    float* visibility = visibility_.row(y);
    OriginTriangle triangle;  // the row's last visible triangle (RayOrigins::start)
    std::vector<vec2> samples(static_cast<size_t>(n_));
    std::vector<int> sample_of(static_cast<size_t>(n_));  // a traced ray's sample
    const bool fixed = options_.samples == SampleSet::Fixed;
    if (fixed) fixedSamples(n_, options_.seed, samples.data());
    std::vector<ShadowRay> rays(static_cast<size_t>(n_));
    std::vector<uint8_t> blocked(static_cast<size_t>(n_));
    for (int x = 0; x < eye_.depth.width(); ++x) {
      if (!(depth[x] > 0.0f)) continue;
      ++counters.z_reads;
      const RayStart start =
          origins_.start(x, y, depth[x], primitive ? primitive[x] : kNoPrimitive, triangle);
      if (!fixed) stratifiedSamples(n_, options_.seed, uint32_t(x), uint32_t(y), samples.data());
      size_t traced = 0;
      if (planar_) {
        traced = aimAtPlanarLight(start, samples, rays, sample_of);
      } else if (glm::length(center_ - start.origin) <= radius_) {
        continue;  // a point inside the light sees all of it
      } else {
        traced = aimAtSphereLight(start, samples, rays);
      }
      bvh_.occluded(rays.data(), traced, simd_, blocked.data());
      int unblocked = 0;
      for (size_t k = 0; k < traced; ++k) unblocked += blocked[k] ? 0 : 1;
      visibility[x] = float(unblocked) / float(n_);
      counters.rays += uint64_t(n_);
      if (textured_) weighByTexture(x, y, samples, sample_of, blocked, traced);
    }
  }

 private:
  // Disk and rectangle lights: rays to points uniform in the light's area (light.h:
  // visibility is the fraction of the area seen). Returns the rays traced.
  size_t aimAtPlanarLight(const RayStart& start, const std::vector<vec2>& samples,
                          std::vector<ShadowRay>& rays, std::vector<int>& sample_of) const {
    const vec3 origin(start.origin);
    size_t traced = 0;
    for (int k = 0; k < n_; ++k) {
      const dvec3 target = planarLightPoint(light_, samples[size_t(k)]);
      const dvec3 to_target = target - start.origin;
      const double distance = glm::length(to_target);
      if (!(distance > 0.0)) continue;  // the point is on the light: nothing in between
      if (start.intoSurface(target)) continue;
      sample_of[traced] = k;
      rays[traced++] = makeRay(origin, vec3(to_target / distance), distance);
    }
    return traced;
  }

  // A sphere light: rays over the cone it fills seen from the point. Returns the rays traced.
  size_t aimAtSphereLight(const RayStart& start, const std::vector<vec2>& samples,
                          std::vector<ShadowRay>& rays) const {
    const vec3 origin(start.origin);
    size_t traced = 0;
    const SphereCone cone = makeSphereCone(start.origin, center_, radius_);
    for (int k = 0; k < n_; ++k) {
      const ConeSample s = sampleSphereCone(cone, concentricDisk(samples[size_t(k)]));
      if (start.intoSurface(start.origin + dvec3(s.direction) * double(s.distance))) {
        continue;  // blocked by the surface itself
      }
      rays[traced++] = makeRay(origin, s.direction, s.distance);
    }
    return traced;
  }

  // Each sample weighs what the texture emits there; samples not traced (behind the surface)
  // count as blocked, as in traceSoftRow.
  void weighByTexture(int x, int y, const std::vector<vec2>& samples,
                      const std::vector<int>& sample_of, const std::vector<uint8_t>& blocked,
                      size_t traced) const {
    dvec3 seen(0.0), all(0.0);
    for (int k = 0; k < n_; ++k) all += dvec3(light_.texture->at(samples[size_t(k)]));
    for (size_t k = 0; k < traced; ++k) {
      if (!blocked[k]) seen += dvec3(light_.texture->at(samples[size_t(sample_of[k])]));
    }
    for (int c = 0; c < 3; ++c) {
      channels_[size_t(c)].at(x, y) = all[c] > 0.0 ? float(seen[c] / all[c]) : 1.0f;
    }
  }

  const Light& light_;
  const ReferenceOptions& options_;
  const EmbreeScene& bvh_;
  const RayOrigins& origins_;
  const EyeBuffers& eye_;
  Image<float>& visibility_;
  ChannelVisibility& channels_;
  const bool simd_;
  const int n_;
  const dvec3 center_;
  const double radius_;
  const bool planar_, textured_;
};

TechniqueResult Oracle::render(const Light& light, const View& view, const EyeBuffers& eye,
                               const RenderContext& context) const {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  PENUMBRA_CHECK(std::isfinite(light.radius) && light.radius >= 0.0f,
                 "light radius {} must be a finite number >= 0", light.radius);
  checkLightShape(light);
  const int width = eye.depth.width();
  const int height = eye.depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  PENUMBRA_CHECK(eye.primitive.empty() ||
                     (eye.primitive.width() == width && eye.primitive.height() == height),
                 "eye primitive ids are {}x{} but the depth buffer is {}x{}",
                 eye.primitive.width(), eye.primitive.height(), width, height);

  const RayOrigins origins(scene_, view);
  origins.checkPrimitiveIds(eye.primitive);

  TechniqueResult result;
  result.visibility.resize(width, height, 1.0f);
  Stats& stats = result.stats;

  PassTimer timer(stats, "reference");
  const bool hard = options_.hard || light.radius == 0.0f;
  std::vector<RowCounters> row_counters(static_cast<size_t>(height));
  // A textured light (light.h): each sample weighs the texel it lands on, per channel.
  const bool textured = !hard && light.texture != nullptr;
  ChannelVisibility channels;
  if (textured) {
    for (Image<float>& c : channels) c.resize(width, height, 1.0f);
  }
  ProgressBar progress("reference", uint64_t(height), context.show_progress);
  const OracleRows rows(light, options_, bvh_, origins, eye, context.simd, hard,
                        result.visibility, channels);
  // One work item per row: rows never share pixels, each pixel's rays are a function of the
  // pixel alone, and counters are summed in row order, so results do not depend on threads.
  parallelFor(size_t(height), [&](size_t row) {
    if (hard) {
      rows.traceHardRow(int(row), row_counters[row]);
    } else {
      rows.traceSoftRow(int(row), row_counters[row]);
    }
    progress.add();
  });
  progress.finish();

  for (const RowCounters& c : row_counters) {
    stats.z_reads += c.z_reads;
    stats.rays += c.rays;
  }
  if (textured) setChannelVisibility(result, light, std::move(channels));
  return result;
}

}  // namespace

TechniqueInfo referenceTechnique() {
  TechniqueInfo info;
  info.name = "reference";
  info.aliases = {"oracle"};
  info.summary = "the ray-traced oracle (Embree): one ray to the light centre, or N stratified "
                 "rays over the light (sphere, disk or rectangle)";
  info.traits.soft = true;
  info.traits.ray_traced = true;
  // Its own sampling noise against 1024 rays, at the default 256 rays.
  info.traits.covered_mae_bound = 0.01;
  info.traits.penumbra_mae_bound = 0.03;
  OptionTableBuilder<ReferenceOptions> table;
  // Previews while the view moves: 16 rays, a sixteenth of the default's work.
  table.integer("rays", "rays per pixel over the light", &ReferenceOptions::rays, 1, kMaxRays)
      .preview("16")
      .flag("hard", "one ray to the light centre, whatever its radius", &ReferenceOptions::hard);
  info.options = seedOption(table, "the ray directions", &ReferenceOptions::seed)
                     .choice("sample-set",
                             "light samples: jittered per pixel (pixel), or one set for every "
                             "pixel (fixed: the set `exact` counts, for sample-by-sample "
                             "comparison)",
                             &ReferenceOptions::samples,
                             {{"pixel", SampleSet::PerPixel}, {"fixed", SampleSet::Fixed}})
                     .describe([](const ReferenceOptions& o) {
                       return o.hard ? std::string("hard")
                                     : fmt::format("{} rays{}", o.rays,
                                                   o.samples == SampleSet::Fixed ? ", fixed" : "");
                     })
                     .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<Oracle>(std::any_cast<const ReferenceOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
