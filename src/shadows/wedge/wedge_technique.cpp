// Penumbra wedge soft shadows: the 2002 algorithm and the 2004 restructured algorithm in its
// three-pass and single-pass implementations (2004 paper, sections 3-6).
//
// The wedges' triangles (light_wedges.h) are set up once per light; every pass bins the ones it
// draws from that one setup.
//
// Restructured (section 3): rasterizeUmbra(front planes, -255) with the depth test, then
// rasterizePenumbra(front-facing wedge faces): for each pixel, if the depth-buffer point is
// inside the wedge, add round(255 s). Back planes are never drawn for the umbra. With z-fail
// (section 5) the umbra volume is closed by caps and counted from infinity, and the penumbra
// footprint is walked through the back-facing faces instead, which also covers the eye being
// inside a wedge (no face of it is then front-facing).
//   three-pass (6.1): umbra into a stencil, stencil x 255 into an LI buffer cleared to 255,
//     then the penumbra pass.
//   single-pass (6.2): one walk over all triangles; a front plane that is also a penumbra face
//     does both parts with one depth read and one LI write; its umbra part is culled with the
//     z-max test only (z-min with z-fail), its penumbra part with the full test.
#include "shadows/wedge/wedge_technique.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/cull_tiles.h"
#include "raster/fixed_point.h"
#include "raster/rasterizer.h"
#include "raster/tile_copy.h"
#include "raster/tile_offsets.h"
#include "shadows/shared_options.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/silhouettes/edge_on_sheet.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/stages/silhouettes/silhouette_layer.h"
#include "shadows/wedge/li_buffer.h"
#include "shadows/wedge/light_wedges.h"
#include "shadows/wedge/wedge2002_kernel.h"
#include "shadows/wedge/wedge_culling.h"
#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {
namespace {

struct WedgeTileWork {
  WedgeKernelCounts umbra, penumbra;
  CullTally tally;
  uint64_t accepted = 0;  // culling tiles whose umbra part went to the coarse level
};

// The debug layers a pass draws into (RenderContext::debug_layers); null: none. Each bin
// tile's worker writes its own pixels only.
struct WedgePassLayers {
  Image<float>* culled = nullptr;      // kCulledTilesLayer
  Image<float>* footprints = nullptr;  // kWedgeFootprintsLayer
};

// The pixels of a wedge face's rect that the penumbra kernel tests, counted in the footprint
// layer.
void markFootprint(const WedgePassLayers& layers, const TileEdges& rect) {
  if (layers.footprints == nullptr) return;
  forEachCoveredPixel(rect, [&](int x, int y) { layers.footprints->at(x, y) += 1.0f; });
}

std::vector<WedgeCullPlanes> cullPlanes(const LightWedges& light_wedges, int width, int height) {
  std::vector<WedgeCullPlanes> planes(light_wedges.screen.size());
  for (size_t i = 0; i < planes.size(); ++i)
    planes[i] = wedgeCullPlanes(light_wedges.screen[i], width, height);
  return planes;
}

// One counter set per bin tile (forEachBinTile hands out bin tile indices), summed in
// tile order so counts do not depend on the thread count.
size_t binTileCount(int width, int height) {
  return size_t((width + kBinTileSize - 1) / kBinTileSize) *
         size_t((height + kBinTileSize - 1) / kBinTileSize);
}

void addTileWork(const std::vector<WedgeTileWork>& tiles, Stats& stats) {
  for (const WedgeTileWork& t : tiles) {
    stats.pixels_rasterized += t.umbra.covered + t.penumbra.covered;
    stats.z_reads += t.umbra.covered + t.penumbra.covered;
    stats.stencil_writes += t.umbra.writes + t.penumbra.writes;
    stats.penumbra_tests += t.penumbra.covered;
    stats.penumbra_inside += t.penumbra.inside;
    stats.tiles_tested += t.tally.tested;
    stats.tiles_culled += t.tally.culled;
    stats.tiles_accepted += t.accepted;
  }
}

// Whether a wedge face takes part in the penumbra walk: front-facing with z-pass, back-facing
// with z-fail (section 5).
bool penumbraFace(const WedgeRole& role, const SetupTriangle& t) {
  if (role.wedge == kNoWedge) return false;
  const int facing = t.facing * role.face_sign;
  return role.zfail ? facing < 0 : facing > 0;
}

int32_t umbraValue(const WedgeRole& role, const SetupTriangle& t, int full) {
  // As rasterizeStencil: +w for polygons facing the eye with z-pass, negated with z-fail; each
  // counted volume takes `full` off the LI buffer.
  return -full * role.umbra_weight * t.facing * (role.zfail ? -1 : 1);
}

// Three-pass, pass 1 and 2: the umbra volume into a stencil buffer, then LI = full - full * s.
// The stencil is read as 8 bits wrapping around, as the papers' hardware stencil.
void umbraThroughStencil(const LightWedges& light_wedges, const std::vector<SetupTriangle>& setup,
                         const WedgeOptions& options, const RenderContext& context,
                         const EyeBuffers& eye, int full, LiBuffer& li, Stats& stats,
                         const WedgePassLayers& layers) {
  // The umbra volume's triangles with their stencil weights as payload (rasterizer.h); the
  // light wedges' setup already carries the z-fail flag.
  std::vector<SetupTriangle> umbra;
  for (const SetupTriangle& t : setup) {
    const int32_t weight = light_wedges.roles[size_t(t.payload)].umbra_weight;
    if (weight == 0) continue;
    umbra.push_back(t);
    umbra.back().payload = weight;
  }
  Image<int32_t> stencil(li.width(), li.height(), 0);
  StencilOptions so;
  so.simd = context.simd;
  so.tile_culling = options.cull != CullMode::None;
  so.cull_level = options.umbra_tile_level > 0 ? options.umbra_tile_level : options.tile_level;
  so.two_level = options.two_level_stencil && options.cull == CullMode::Full;
  so.culled_layer = layers.culled;
  rasterizeStencil(umbra, eye.depth, stencil, stats, so);
  parallelFor(size_t(li.height()), [&](size_t y) {
    for (int x = 0; x < li.width(); ++x)
      li.at(x, int(y)) = liAdd(int16_t(full), -full * int32_t(int8_t(stencil.at(x, int(y)))));
  });
}

// The scaffolding of the wedge passes: `setup` is the wedges' set-up triangles, taken by value
// and filtered in place to those the pass draws (keep(role, triangle)); for every bin tile that
// holds one of them, on the worker owning it, fn(triangle, rect, target, coarse,
// tile_work) for those triangles in input order, where target() gives the tile's depth and LI
// in L1 copies (raster/tile_copy.h), made on first use and the LI stored back at the end of the
// tile, and `coarse` holds umbra values per culling tile of 2^coarse_level pixels, added to
// the LI (wrapping) before it is stored (two-level stencil, raster/tile_offsets.h). Counters
// are summed in tile order.
template <class Keep, class Fn>
void forEachWedgeTriangle(const LightWedges& light_wedges, std::vector<SetupTriangle> setup,
                          const EyeBuffers& eye, LiBuffer& li, Stats& stats, int coarse_level,
                          Image<float>* culled_layer, Keep&& keep, Fn&& fn) {
  const int width = li.width(), height = li.height();
  std::vector<WedgeTileWork> work(binTileCount(width, height));
  for (WedgeTileWork& w : work) w.tally.culled_layer = culled_layer;
  struct Copies {
    Copies(const Image<float>& depth_image, const LiBuffer& li_image, const TileBox& box)
        : depth(depth_image, box), li(li_image, box) {}
    TileCopy<float> depth;
    TileCopy<int16_t> li;
  };
  std::erase_if(setup, [&](const SetupTriangle& t) {
    return !keep(light_wedges.roles[size_t(t.payload)], t);
  });
  forEachBinTile(
      setup, width, height,
      [&](const TileTriangles& tile) {
        const TileBox& box = tile.box();
        std::optional<Copies> copies;
        WedgeKernelTarget tile_target{nullptr, nullptr, kBinTileSize, box.x0, box.y0};
        auto target = [&]() -> const WedgeKernelTarget& {
          if (!copies) {
            copies.emplace(eye.depth.depth, li, box);
            tile_target.depth = copies->depth.data();
            tile_target.li = copies->li.data();
          }
          return tile_target;
        };
        WedgeTileWork& tw = work[tile.index()];
        TileOffsets coarse(coarse_level);
        tile.forEach([&](const SetupTriangle& t, TileEdges& e) { fn(t, e, target, coarse, tw); });
        if (coarse.used()) {
          target();
          coarse.applyTo(
              copies->li.data(), box, [](int16_t& v, int32_t sum) { v = liAdd(v, sum); },
              tw.umbra.writes, tw.accepted);
        }
        if (copies) copies->li.storeTo(li, box);
      });
  addTileWork(work, stats);
}

void penumbraPass(const LightWedges& light_wedges, std::vector<SetupTriangle> setup,
                  const WedgeOptions& options, const RenderContext& context,
                  const EyeBuffers& eye, int full, LiBuffer& li, Stats& stats,
                  const WedgePassLayers& layers) {
  const std::vector<WedgeCullPlanes> planes = cullPlanes(light_wedges, li.width(), li.height());
  forEachWedgeTriangle(
      light_wedges, std::move(setup), eye, li, stats, options.tile_level, layers.culled,
      penumbraFace,
      [&](const SetupTriangle& t, TileEdges& e, auto& target, TileOffsets&, WedgeTileWork& tw) {
        const WedgeRole& role = light_wedges.roles[size_t(t.payload)];
        WedgeKernelWork k;
        k.wedge = &light_wedges.screen[size_t(role.wedge)];
        k.li_scale = float(full);
        forEachCullRect(
            t, e, eye.depth, options.tile_level,
            [&](const TileEdges& sub, float zmin, float zmax) {
              return penumbraCulled(options.cull, planes[size_t(role.wedge)], sub, zmin, zmax) ? 0
                                                                                              : 1;
            },
            [&](const TileEdges& rect, int) {
              wedgeKernel(rect, k, target(), tw.penumbra, context.simd);
              markFootprint(layers, rect);
            },
            tw.tally);
      });
}

void singlePass(const LightWedges& light_wedges, std::vector<SetupTriangle> setup,
                const WedgeOptions& options, const RenderContext& context, const EyeBuffers& eye,
                int full, LiBuffer& li, Stats& stats, const WedgePassLayers& layers) {
  const std::vector<WedgeCullPlanes> planes = cullPlanes(light_wedges, li.width(), li.height());
  const bool two_level = options.two_level_stencil && options.cull == CullMode::Full;
  forEachWedgeTriangle(
      light_wedges, std::move(setup), eye, li, stats, options.tile_level, layers.culled,
      [](const WedgeRole& role, const SetupTriangle& t) {
        return role.umbra_weight != 0 || penumbraFace(role, t);
      },
      [&](const SetupTriangle& t, TileEdges& e, auto& target, TileOffsets& coarse,
          WedgeTileWork& tw) {
        const WedgeRole& role = light_wedges.roles[size_t(t.payload)];
        const bool has_penumbra = penumbraFace(role, t);
        const ScreenWedge* wedge =
            has_penumbra ? &light_wedges.screen[size_t(role.wedge)] : nullptr;
        // Per culling tile, which parts run there: bit 0 the umbra, bit 1 the penumbra, bit 2
        // the umbra as one coarse value for the whole tile (two-level stencil).
        constexpr int kUmbra = 1, kPenumbra = 2, kUmbraWhole = 4;
        forEachCullRect(
            t, e, eye.depth, options.tile_level,
            [&](const TileEdges& sub, float zmin, float zmax) {
              int parts = 0;
              if (role.umbra_weight != 0) {
                const DepthRuleTiles umbra =
                    options.cull == CullMode::None
                        ? DepthRuleTiles::Some
                        : depthRuleTiles(t, sub, role.zfail, zmin, zmax, two_level);
                if (umbra != DepthRuleTiles::None) parts |= kUmbra;
                if (umbra == DepthRuleTiles::All) parts |= kUmbraWhole;
              }
              if (wedge != nullptr &&
                  !penumbraCulled(options.cull, planes[size_t(role.wedge)], sub, zmin, zmax))
                parts |= kPenumbra;
              return parts;
            },
            [&](const TileEdges& rect, int parts) {
              WedgeKernelWork k;
              k.li_scale = float(full);
              if (parts & kUmbraWhole) {
                coarse.add(rect, umbraValue(role, t, full));
              } else if (parts & kUmbra) {
                k.umbra_value = umbraValue(role, t, full);
                k.rule = role.zfail ? DepthRule::NotCloser : DepthRule::Closer;
              }
              if (parts & kPenumbra) {
                k.wedge = wedge;
                markFootprint(layers, rect);
              }
              if (k.umbra_value == 0 && k.wedge == nullptr) return;
              // One depth read per pixel for both parts: count it under the penumbra when
              // that part runs, else under the umbra.
              wedgeKernel(rect, k, target(), k.wedge != nullptr ? tw.penumbra : tw.umbra,
                          context.simd);
            },
            tw.tally, kUmbraWhole);
      });
}

void original2002(const LightWedges& light_wedges, std::vector<SetupTriangle> setup,
                  const WedgeOptions& options, const RenderContext& context,
                  const EyeBuffers& eye, int full, LiBuffer& li, Stats& stats,
                  const WedgePassLayers& layers) {
  // Entries (front-facing wedge faces) and umbra quads; back-facing wedge faces add nothing.
  const auto entry = [](const WedgeRole& role, const SetupTriangle& t) {
    return role.wedge != kNoWedge && t.facing * role.face_sign > 0;
  };
  forEachWedgeTriangle(
      light_wedges, std::move(setup), eye, li, stats, options.tile_level, layers.culled,
      [&](const WedgeRole& role, const SetupTriangle& t) {
        return entry(role, t) || role.umbra_weight != 0;
      },
      [&](const SetupTriangle& t, TileEdges& e, auto& target, TileOffsets&, WedgeTileWork& tw) {
        const WedgeRole& role = light_wedges.roles[size_t(t.payload)];
        if (!setupRectEdges(t, e)) return;
        ++tw.tally.tested;
        if (!entry(role, t)) {
          // Umbra quads that are not a front-facing wedge face: back-facing front planes, where
          // rays leave a wedge through its front plane (s_i = 1, counted on the rasterized face
          // so that it pairs exactly with the entries the neighbouring wedges rasterize), and
          // quads with no wedge face (zero radius, nearly parallel edges, crossing front rays):
          // wedges of zero thickness, entered and left at once. Where the quad is in front of
          // the point, -255 if it faces the eye, +255 if not (z-pass).
          WedgeKernelWork k;
          k.umbra_value = umbraValue(role, t, full);
          k.rule = DepthRule::Closer;
          wedgeKernel(e, k, target(), tw.umbra, context.simd);
          return;
        }
        wedge2002Kernel(e, light_wedges.screen[size_t(role.wedge)], role.face, float(full),
                        target(), tw.penumbra);
        markFootprint(layers, e);
      });
}

// The main pass's debug layers: the silhouette edges the wedges are built on (each wedge's
// edge a-b), drawn now; the culled tiles and the footprints, for the passes to fill.
WedgePassLayers addWedgeLayers(const LightWedges& light_wedges, const View& view,
                               std::vector<DebugLayer>& layers, bool wanted) {
  if (!wanted) return {};
  Image<float>& edges = debugLayer(layers, kSilhouetteEdgesLayer,
                                   "silhouette edges seen from the light centre, per pixel",
                                   view.width, view.height);
  for (const Wedge& wedge : light_wedges.wedges) {
    drawWorldSegment(view, vec3(wedge.a), vec3(wedge.b), edges);
  }
  debugLayer(layers, kCulledTilesLayer,
             "(umbra quad or wedge face, culling tile) pairs culled, per pixel", view.width,
             view.height);
  debugLayer(layers, kWedgeFootprintsLayer,
             "wedge faces whose penumbra test ran at the pixel after tile culling", view.width,
             view.height);
  // Pointers taken once every layer is in: adding one moves the others.
  return {&debugLayer(layers, kCulledTilesLayer, "", view.width, view.height),
          &debugLayer(layers, kWedgeFootprintsLayer, "", view.width, view.height)};
}

}  // namespace

std::string wedgeTechniqueName(WedgeAlgorithm algorithm) {
  switch (algorithm) {
    case WedgeAlgorithm::Original2002: return "wedge-2002";
    case WedgeAlgorithm::ThreePass: return "wedge-3pass";
    case WedgeAlgorithm::SinglePass: return "wedge-1pass";
  }
  return "unknown";
}

WedgeLi renderWedgeLi(WedgeAlgorithm algorithm, const WedgeOptions& options, const Scene& scene,
                      const Light& light, const View& view, const EyeBuffers& eye,
                      const RenderContext& context, int8_t edge_on_facing,
                      const std::vector<uint8_t>* other_facing_meshes,
                      const CasterCulling* caster_culling) {
  WedgeLi result;
  Stats& stats = result.stats;
  const int full = kLiFull;
  result.full = full;
  LightWedges light_wedges;
  std::vector<SetupTriangle> setup;
  {
    PassTimer timer(stats, "wedges");
    LightWedgesOptions build_options;
    // The 2002 algorithm predates z-fail for wedges (its section 8): always from the eye.
    build_options.volume_mode =
        algorithm == WedgeAlgorithm::Original2002 ? VolumeMode::ZPass : options.volume_mode;
    build_options.smooth_falloff = options.smooth_falloff;
    build_options.edge_on_facing = edge_on_facing;
    build_options.other_facing_meshes = other_facing_meshes;
    build_options.caster_culling = caster_culling;
    light_wedges = buildLightWedges(build_options, scene, light, view, eye);
    stats.silhouette_edges += light_wedges.silhouette_edges;
    stats.wedges += light_wedges.wedges.size();
  }
  if (edge_on_facing != 0 && light_wedges.silhouette_edges == 0) return result;
  const WedgePassLayers layers = addWedgeLayers(light_wedges, view, result.debug_layers,
                                                context.debug_layers && edge_on_facing == 0 &&
                                                    other_facing_meshes == nullptr);
  {
    PassTimer timer(stats, "setup");
    setup = setupTriangles(light_wedges.triangles, view.width, view.height);
    stats.triangles += setup.size();
  }
  LiBuffer& li = result.li;
  li.resize(view.width, view.height, int16_t(full));
  switch (algorithm) {
    case WedgeAlgorithm::ThreePass: {
      {
        PassTimer timer(stats, "umbra");
        umbraThroughStencil(light_wedges, setup, options, context, eye, full, li, stats, layers);
      }
      PassTimer timer(stats, "penumbra");
      penumbraPass(light_wedges, std::move(setup), options, context, eye, full, li, stats,
                   layers);
      break;
    }
    case WedgeAlgorithm::SinglePass: {
      PassTimer timer(stats, "single-pass");
      singlePass(light_wedges, std::move(setup), options, context, eye, full, li, stats, layers);
      break;
    }
    case WedgeAlgorithm::Original2002: {
      PassTimer timer(stats, "wedge-2002");
      original2002(light_wedges, std::move(setup), options, context, eye, full, li, stats,
                   layers);
      break;
    }
  }
  return result;
}

namespace {

class PenumbraWedges final : public PreparedTechnique {
 public:
  PenumbraWedges(WedgeAlgorithm algorithm, const WedgeOptions& options, const Scene& scene)
      : algorithm_(algorithm), options_(options), scene_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override {
    requireSphereLight(light, wedgeTechniqueName(algorithm_));
    Stats culling_stats;
    const CasterCulling culling =
        cullCasters(scene_, light, view, eye, context.caster_culling, culling_stats);
    WedgeLi wedges = renderWedgeLi(algorithm_, options_, scene_, light, view, eye, context, 0,
                                   nullptr, &culling);
    TechniqueResult result;
    result.stats = std::move(culling_stats);
    result.stats.add(wedges.stats);
    result.debug_layers = std::move(wedges.debug_layers);
    const bool hard = !(light.radius > 0.0f);
    // Casters edge-on to the light centre with the facing their meshes do not cast, each
    // facing in a buffer of its own, clamped on its own (edge_on_sheet.h says why); usually
    // none, and then no pass runs. A zero radius has no penumbra and keeps the hard image.
    std::vector<WedgeLi> sheets;
    // Open meshes cast one facing (silhouette.h, SolidWithHoles), so a ray that enters such a
    // mesh through a triangle of the other facing and leaves through a hole (a terrain's border
    // under a low light, a scan's open base) counts nothing and its point comes out lit. The
    // other facing, in a buffer of its own, counts exactly those rays; both facings' passes
    // are single-sided, so their folds keep one wedge each, and the darker visibility is kept.
    const std::vector<uint8_t> other_facing =
        hard || !options_.other_facing_pass ? std::vector<uint8_t>()
                                            : openMeshesWithBothFacings(scene_, light.center);
    if (!other_facing.empty()) {
      PassTimer timer(result.stats, "other facing");
      WedgeLi other =
          renderWedgeLi(algorithm_, options_, scene_, light, view, eye, context, 0, &other_facing,
                        &culling);
      result.stats.addCounters(other.stats);
      sheets.push_back(std::move(other));
    }
    if (!hard && anyEdgeOnToLight(scene_, light)) {
      PassTimer timer(result.stats, "edge-on sheets");
      for (const int8_t facing : {int8_t(1), int8_t(-1)}) {
        WedgeLi sheet =
            renderWedgeLi(algorithm_, options_, scene_, light, view, eye, context, facing,
                          nullptr, &culling);
        result.stats.addCounters(sheet.stats);
        if (sheet.li.width() > 0) sheets.push_back(std::move(sheet));
      }
    }
    PassTimer timer(result.stats, "resolve");
    // As the hard shadow volume and the oracle: a point whose triangle faces away from the
    // whole light gets none of it, whatever the wedges near the terminator say (their
    // silhouette is the centre's for the whole light, 2002 paper, section 8). With a zero
    // radius this keeps the image the hard volume's exactly.
    resolveVisibility(scene_, light, view, eye, result.visibility, [&](int x, int y) {
      float v = liVisibility(wedges.li.at(x, y), wedges.full, hard);
      for (const WedgeLi& sheet : sheets)
        v = std::min(v, liVisibility(sheet.li.at(x, y), sheet.full, false));
      return v;
    });
    return result;
  }

 private:
  WedgeAlgorithm algorithm_;
  WedgeOptions options_;
  const Scene& scene_;
};

}  // namespace

TechniqueInfo wedgeTechnique(WedgeAlgorithm algorithm) {
  TechniqueInfo info;
  info.name = wedgeTechniqueName(algorithm);
  info.counters = casterCullingCounters();
  info.traits.soft = true;
  // The papers' approximation (silhouettes from the light centre, overlapping wedges added),
  // as measured by the conformance suite: penumbra MAE 0.04-0.06 on most built-in scenes and
  // 0.128 on year2002, whose digits' penumbrae overlap on the teapots (2002 paper, section 8;
  // docs/wedge-accuracy.md).
  info.traits.covered_mae_bound = 0.03;
  info.traits.penumbra_mae_bound = 0.15;
  OptionTableBuilder<WedgeOptions> options;
  options.flag("smooth", "smooth falloff s' = 3s^2 - 2s^3 (2002 paper, section 4.2)",
               &WedgeOptions::smooth_falloff);
  options.flag("one-facing",
               "open meshes cast one facing only, as in the papers (faster where an open mesh "
               "faces the light both ways, but light passes through its holes)",
               &WedgeOptions::other_facing_pass, false);
  if (algorithm == WedgeAlgorithm::Original2002) {
    info.summary = "penumbra wedges as in the 2002 paper: z-pass, entry and exit per pixel, "
                   "no culling";
    options.describe([](const WedgeOptions& o) {
      return std::string("zpass") + (o.smooth_falloff ? ", smooth" : "") +
             (o.other_facing_pass ? "" : ", one facing");
    });
  } else {
    info.summary = algorithm == WedgeAlgorithm::ThreePass
                       ? "penumbra wedges, 2004 restructured algorithm, three passes (umbra "
                         "stencil, then penumbra), tile culling, z-fail"
                       : "penumbra wedges, 2004 restructured algorithm, one pass over umbra and "
                         "penumbra, tile culling, z-fail";
    volumeModeOption(options, &WedgeOptions::volume_mode)
        .choice("cull", "tile culling: none, zmax (z-max only) or full (z-min and z-max)",
                &WedgeOptions::cull,
                {{"none", CullMode::None}, {"zmax", CullMode::ZMax}, {"full", CullMode::Full}});
    tileSizeOption(options, "culling", &WedgeOptions::tile_level, kMinTileLevel, kMaxTileLevel)
        .flag("one-level-stencil",
              "umbra pixel by pixel, as the papers' passes (otherwise tiles an umbra polygon "
              "covers and passes whole take one coarse write)",
              &WedgeOptions::two_level_stencil, false);
    if (algorithm == WedgeAlgorithm::ThreePass) {
      options.integer(
          "umbra-tile-size",
          "culling tile size of the umbra pass, a power of two in 2..256; 0: --tile-size",
          0, 1 << kMaxTileLevel,
          [](WedgeOptions& o, int64_t size) {
            o.umbra_tile_level = size == 0 ? 0
                                           : tileLevelOfSize(size, kMinTileLevel, kMaxTileLevel,
                                                             "--umbra-tile-size");
          },
          [](const WedgeOptions& o) {
            return o.umbra_tile_level == 0 ? int64_t(0) : int64_t(1) << o.umbra_tile_level;
          });
    }
    options.describe([](const WedgeOptions& o) {
      const char* stencil =
          o.two_level_stencil || o.cull != CullMode::Full ? "" : ", one-level stencil";
      return fmt::format("{}, cull {}, {}x{} tiles{}{}{}", volumeModeName(o.volume_mode),
                         cullModeName(o.cull), 1 << o.tile_level, 1 << o.tile_level, stencil,
                         o.smooth_falloff ? ", smooth" : "",
                         o.other_facing_pass ? "" : ", one facing");
    });
  }
  options.check([](const WedgeOptions& o) {
    PENUMBRA_CHECK(o.tile_level >= kMinTileLevel && o.tile_level <= kMaxTileLevel,
                   "tile size 2^{} is outside 2^{}..2^{}", o.tile_level, kMinTileLevel,
                   kMaxTileLevel);
    PENUMBRA_CHECK(o.umbra_tile_level == 0 || (o.umbra_tile_level >= kMinTileLevel &&
                                               o.umbra_tile_level <= kMaxTileLevel),
                   "umbra tile size 2^{} is outside 2^{}..2^{}", o.umbra_tile_level,
                   kMinTileLevel, kMaxTileLevel);
  });
  info.options = options.build();
  info.prepare = [algorithm](const std::any& given, const Scene& scene) {
    return std::make_unique<PenumbraWedges>(algorithm, std::any_cast<const WedgeOptions&>(given),
                                            scene);
  };
  return info;
}

}  // namespace penumbra
