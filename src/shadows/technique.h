#pragma once
// The one technique contract (DESIGN.md): given the eye pass's buffers, a light, the scene and
// the view, a technique writes the light visibility of every pixel's visible point, in [0, 1],
// and its work counters. Techniques read the eye buffers and never write them.
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"

namespace penumbra {

enum class TechniqueKind {
  Reference,      // ray-traced oracle (Embree): hard = one ray to the centre, soft = N rays
  ShadowVolume,   // hard shadow volumes, z-pass / z-fail, integer stencil
};

// How shadow volumes count: from the eye (z-pass, Heidmann) or from infinity (z-fail,
// Everitt & Kilgard). Auto picks z-fail per caster only where the eye may be inside its volume.
enum class VolumeMode { Auto, ZPass, ZFail };

struct TechniqueOptions {
  TechniqueKind kind = TechniqueKind::ShadowVolume;
  VolumeMode volume_mode = VolumeMode::Auto;
  // Oracle: rays per pixel over the spherical light (1..4096); with a point light (radius 0),
  // or when `hard` is set, one ray to the light centre.
  int rays = 256;
  bool hard = false;
  uint64_t seed = 1;
  bool simd = true;           // false: run every hot loop's scalar twin
  bool show_progress = false; // progress bar on a terminal for long work
};

struct TechniqueResult {
  Image<float> visibility;  // per pixel, in [0, 1]; 1 on background pixels
  Stats stats;
};

TechniqueResult renderShadows(const TechniqueOptions& options, const Scene& scene,
                              const Light& light, const View& view, const EyeBuffers& eye);

// Name <-> kind, for the CLI and stats files ("reference", "volume").
std::string techniqueName(TechniqueKind kind);
TechniqueKind parseTechniqueName(const std::string& name);  // throws penumbra::Error
std::vector<std::string> techniqueNames();

}  // namespace penumbra
