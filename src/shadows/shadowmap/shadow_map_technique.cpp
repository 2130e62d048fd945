// The standard shadow map (Williams 1978), as reviewed in Aila's 2005 thesis, section 2.3.
//
// The light's view is always a cube map: six square 90-degree faces around the light centre,
// one View each (View::lookAt), so a light anywhere, inside the view or among the geometry, is
// covered; a spot frustum for a light outside the scene's bounds would be an optimisation and is
// not made. Every scene triangle is drawn into every face with the eye pass's own depth
// rasterizer (rasterizeDepth: tiled, multithreaded, reversed-Z, 0 = nothing drawn). Per pixel of
// the eye buffers the visible point p picks the face of its major axis from the light, is
// projected into it, and an N x N kernel of stored depths around the projected position is
// compared with p's distance along the face's axis (linear: w = near / depth), less a bias;
// visibility is the fraction of lookups that find no occluder in front (percentage-closer
// filtering, Reeves, Salesin & Cook 1987).
//
// The lookup loop is scalar in this version (RenderContext::simd reaches the rasterizer only).
//
// Counters: the faces' rasterization counts its own (pixels_rasterized, z_reads,
// stencil_writes as depth writes, triangles); the lookups add N x N depth-buffer reads per
// resolved pixel to z_reads (pixels facing away from the light take none).
#include "shadows/shadowmap/shadow_map_technique.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "raster/rasterizer.h"
#include "shadows/facing_away.h"

namespace penumbra {
namespace {

constexpr int kFaces = 6;

// The near plane of every face, as a fraction of the distance from the light centre to the
// farthest corner of the scene's bounds. Reversed-Z float depth (near / w) keeps the same
// relative precision at every distance, so a small near plane costs no depth precision; it only
// clips away geometry closer to the light than this (1e-6 of the scene: nothing in practice),
// whatever the scene's units.
constexpr double kNearFraction = 1e-6;

// The slope-scaled bias grows with tan(angle between the surface normal and the light
// direction), which is unbounded at grazing angles; beyond this it stops growing (the point is
// then almost on its own terminator, where the facing test of resolveVisibility takes over).
constexpr double kMaxSlope = 10.0;

struct Face {
  vec3 axis, up;
};
// +X, -X, +Y, -Y, +Z, -Z; any up not parallel to the axis will do.
constexpr std::array<Face, kFaces> kCubeFaces = {{
    {vec3(1, 0, 0), vec3(0, 1, 0)},
    {vec3(-1, 0, 0), vec3(0, 1, 0)},
    {vec3(0, 1, 0), vec3(0, 0, 1)},
    {vec3(0, -1, 0), vec3(0, 0, 1)},
    {vec3(0, 0, 1), vec3(0, 1, 0)},
    {vec3(0, 0, -1), vec3(0, 1, 0)},
}};

// The face whose axis is p's major axis from the light (the first on a tie): p then projects
// inside that face's 90-degree frustum.
int majorFace(const dvec3& d) {
  const dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

class ShadowMap final : public PreparedTechnique {
 public:
  ShadowMap(const ShadowMapOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {
    // Per scene: the triangle list the faces draw (indices into the scene's vertices, mesh after
    // mesh); per light only the clip-space vertices change.
    size_t base = 0;
    for (const Mesh& mesh : scene.meshes) {
      for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        triangles_.add(uint32_t(base + mesh.indices[t * 3]),
                       uint32_t(base + mesh.indices[t * 3 + 1]),
                       uint32_t(base + mesh.indices[t * 3 + 2]), 0, 0);
      }
      base += mesh.positions.size();
    }
    vertex_count_ = base;
    const Bounds3 bounds = scene.bounds();
    if (!bounds.empty()) {
      bounds_min_ = dvec3(bounds.min);
      bounds_max_ = dvec3(bounds.max);
      has_geometry_ = true;
    }
  }

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    requireSphereLight(light, "shadow-map");
    TechniqueResult result;
    Stats& stats = result.stats;
    const int size = options_.resolution;
    const dvec3 centre(light.center);

    // The near plane from the scene's scale: a fraction of the distance to its farthest corner.
    double far = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const dvec3 q(corner & 1 ? bounds_max_.x : bounds_min_.x,
                    corner & 2 ? bounds_max_.y : bounds_min_.y,
                    corner & 4 ? bounds_max_.z : bounds_min_.z);
      far = std::max(far, glm::length(q - centre));
    }
    const float near_plane =
        has_geometry_ && far > 0.0 ? float(far * kNearFraction) : 1.0f;

    std::array<View, kFaces> faces;
    std::array<Image<float>, kFaces> depth;
    {
      PassTimer timer(stats, "shadow map");
      std::vector<vec4> clip(vertex_count_);
      ClipTriangles tris = triangles_;
      Image<uint32_t> ids;  // rasterizeDepth's primitive ids, not needed here
      ids.resizeForOverwrite(size, size);
      for (int f = 0; f < kFaces; ++f) {
        faces[f] = View::lookAt(size, size, light.center, light.center + kCubeFaces[f].axis,
                                kCubeFaces[f].up, 90.0f, near_plane);
        const View& face = faces[f];
        size_t base = 0;
        for (const Mesh& mesh : scene_.meshes) {
          parallelFor((mesh.positions.size() + 4095) / 4096, [&](size_t chunk) {
            const size_t end = std::min(mesh.positions.size(), (chunk + 1) * 4096);
            for (size_t i = chunk * 4096; i < end; ++i)
              clip[base + i] = face.toClip(vec4(mesh.positions[i], 1.0f));
          });
          base += mesh.positions.size();
        }
        tris.shared = clip.data();
        tris.shared_count = clip.size();
        depth[f].resizeForOverwrite(size, size);
        rasterizeDepth(tris, depth[f], ids, stats, context.simd);
      }
    }

    {
      PassTimer timer(stats, "lookups");
      std::array<dmat4, kFaces> face_matrix;
      for (int f = 0; f < kFaces; ++f) face_matrix[f] = dmat4(faces[f].view_projection);
      const int kernel = options_.pcf_kernel;
      const double reach = 0.5 * double(kernel + 1);  // texels from p to the farthest lookup
      const double near = double(near_plane);
      std::vector<uint64_t> row_reads(size_t(view.height), 0);
      resolveVisibility(scene_, light, view, eye, result.visibility, [&](int x, int y) {
        const dvec3 p = view.unproject(x, y, eye.depth.depth.at(x, y));
        const int f = majorFace(p - centre);
        const dvec4 c = face_matrix[f] * dvec4(p, 1.0);
        const double w = c.w;  // p's distance along the face's axis
        if (!(w > 0.0)) return 1.0f;  // at the light centre itself
        const double sx = (c.x / w * 0.5 + 0.5) * size;
        const double sy = (0.5 - c.y / w * 0.5) * size;
        // Bias, in world units along the axis: one texel spans 2 w / size at p's distance.
        const double texel = 2.0 * w / size;
        double slope = 0.0;
        {
          const auto [m, t] = scene_.locateTriangle(eye.primitive.at(x, y));
          const Mesh& mesh = scene_.meshes[m];
          const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), cc(mesh.vertex(t, 2));
          const dvec3 n = glm::cross(b - a, cc - a);
          const dvec3 l = centre - p;
          const double nl = glm::length(n) * glm::length(l);
          const double cosine = nl > 0.0 ? std::fabs(glm::dot(n, l)) / nl : 1.0;
          const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
          slope = sine < kMaxSlope * cosine ? sine / cosine : kMaxSlope;
        }
        const double bias = texel * (options_.constant_bias + options_.slope_bias * slope * reach);
        const double receiver = w - bias;
        // Kernel of texel centres nearest the projected position; lookups past a face's border
        // are clamped to its edge texels instead of continuing on the neighbouring face, a known
        // approximation that only matters for kernels straddling a cube edge.
        const int x0 = int(std::floor(sx - 0.5 * (kernel - 1)));
        const int y0 = int(std::floor(sy - 0.5 * (kernel - 1)));
        const Image<float>& map = depth[f];
        int lit = 0;
        for (int j = 0; j < kernel; ++j) {
          const float* row = map.row(std::clamp(y0 + j, 0, size - 1));
          for (int i = 0; i < kernel; ++i) {
            const float stored = row[std::clamp(x0 + i, 0, size - 1)];
            // Stored 0: nothing drawn there (lit); else the occluder's distance near / depth.
            lit += stored == 0.0f || near / double(stored) >= receiver;
          }
        }
        row_reads[size_t(y)] += uint64_t(kernel) * uint64_t(kernel);
        return float(lit) / float(kernel * kernel);
      });
      for (const uint64_t reads : row_reads) stats.z_reads += reads;
    }
    return result;
  }

 private:
  ShadowMapOptions options_;
  const Scene& scene_;
  ClipTriangles triangles_;
  size_t vertex_count_ = 0;
  dvec3 bounds_min_{0.0}, bounds_max_{0.0};
  bool has_geometry_ = false;
};

}  // namespace

TechniqueInfo shadowMapTechnique() {
  TechniqueInfo info;
  info.name = "shadow-map";
  info.summary = "standard shadow map: cube map of depth from the light centre, bias, PCF";
  // Hard, approximate: the shadow boundary moves by up to a texel (PCF blurs it over the kernel)
  // and the bias lights a thin band at contact. Measured with the defaults (1024 texels, 3 x 3
  // PCF) against the one-ray oracle at the conformance suite's 160 x 107, commit introducing
  // this technique: MAE over covered pixels spheres 0.0033, columns 0.0099, fractal 0.0093,
  // year2002 0.0058, multilight 0.0028; the bound leaves half again of the largest.
  info.traits.covered_mae_bound = 0.015;
  info.options =
      OptionTableBuilder<ShadowMapOptions>()
          .integer("shadow-map-size", "texels along each side of each of the six cube faces",
                   &ShadowMapOptions::resolution, 16, 4096)
          .integer("pcf-kernel",
                   "percentage-closer filtering over N x N lookups (1: plain shadow map)",
                   &ShadowMapOptions::pcf_kernel, 1, 15)
          .number("constant-bias", "depth bias in texels at the receiver's distance",
                  &ShadowMapOptions::constant_bias, 0.0, 1000.0)
          .number("slope-bias",
                  "slope-scaled depth bias: x tan(normal, light direction) x the kernel's reach "
                  "in texels",
                  &ShadowMapOptions::slope_bias, 0.0, 1000.0)
          .describe([](const ShadowMapOptions& o) {
            return fmt::format("{}^2 x 6 faces, pcf {}x{}, bias {} + {} slope", o.resolution,
                               o.pcf_kernel, o.pcf_kernel, formatNumber(o.constant_bias),
                               formatNumber(o.slope_bias));
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<ShadowMap>(std::any_cast<const ShadowMapOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
