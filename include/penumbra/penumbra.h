#pragma once
// Penumbra's public API: load a scene, render a frame with a shadow technique, write
// and compare the results.
//
//   penumbra::Scene scene = penumbra::loadScene("spheres");   // or a .json scene, or a mesh
//   penumbra::FrameOptions options;
//   options.technique = penumbra::TechniqueConfig("reference");
//   options.technique.set("rays", "64");                       // an option as on the command line
//   penumbra::FrameResult frame = penumbra::renderFrame(scene, options);
//   penumbra::writePng("out/spheres.png", frame.color);
//   penumbra::writeExr("out/vis.exr", frame.lights[0].visibility);
//   penumbra::ImageDifference d =
//       penumbra::compareImages(frame.lights[0].visibility, other_visibility, 0.01);
//
// A technique's options are also a plain struct (shadows/*_options.h), for typed access:
//
//   penumbra::TechniqueConfig wedges("wedge-3pass");
//   wedges.options<penumbra::WedgeOptions>().cull = penumbra::CullMode::ZMax;
//
// A frame loop prepares the technique for the scene once (the oracle's BVH, say):
//
//   penumbra::FrameRenderer renderer(scene, options);
//   penumbra::FrameResult frame;
//   for (...) renderer.render(frame);   // reuses frame's memory
//
// Installed, the headers are <penumbra/...> under the package's include folder:
// find_package(Penumbra) and link Penumbra::penumbra (README, "Use it as a library").
// Every error a caller can cause throws penumbra::Error with a message naming the input.

#include <penumbra/core/error.h>
#include <penumbra/core/image.h>
#include <penumbra/core/image_io.h>
#include <penumbra/core/math.h>
#include <penumbra/core/parallel.h>
#include <penumbra/core/stats.h>
#include <penumbra/core/view.h>
#include <penumbra/metrics/heatmap.h>
#include <penumbra/metrics/image_compare.h>
#include <penumbra/raster/depth_buffer.h>
#include <penumbra/render/frame.h>
#include <penumbra/render/stats_json.h>
#include <penumbra/scene/builtin_scenes.h>
#include <penumbra/scene/camera.h>
#include <penumbra/scene/edges.h>
#include <penumbra/scene/instances.h>
#include <penumbra/scene/light.h>
#include <penumbra/scene/load_mesh.h>
#include <penumbra/scene/material.h>
#include <penumbra/scene/mesh_arrays.h>
#include <penumbra/scene/mesh.h>
#include <penumbra/scene/path.h>
#include <penumbra/scene/scene.h>
#include <penumbra/scene/scene_file.h>
#include <penumbra/scene/up_axis.h>
#include <penumbra/shadows/alias_free_options.h>
#include <penumbra/shadows/coverage_options.h>
#include <penumbra/shadows/exact_options.h>
#include <penumbra/shadows/heckbert_herf_options.h>
#include <penumbra/shadows/mask_options.h>
#include <penumbra/shadows/pcss_options.h>
#include <penumbra/shadows/reference_options.h>
#include <penumbra/shadows/shadow_map_options.h>
#include <penumbra/shadows/technique.h>
#include <penumbra/shadows/technique_options.h>
#include <penumbra/shadows/volume_options.h>
#include <penumbra/shadows/wedge_options.h>
