#pragma once
// Penumbra's public API (DESIGN.md): load a scene, render a frame with a shadow technique, write
// and compare the results.
//
//   penumbra::Scene scene = penumbra::loadScene("spheres");   // or a .json scene, or a mesh
//   penumbra::FrameOptions options;
//   options.technique.kind = penumbra::parseTechniqueName("reference");
//   penumbra::FrameResult frame = penumbra::renderFrame(scene, options);
//   penumbra::writePng("out/spheres.png", frame.color);
//   penumbra::writeExr("out/vis.exr", frame.lights[0].visibility);
//   penumbra::ImageDifference d =
//       penumbra::compareImages(frame.lights[0].visibility, other_visibility, 0.01);
//
// The headers below live in the library's src/ folder, which must be on the include path.
// Every error a caller can cause throws penumbra::Error with a message naming the input.

#include "core/error.h"
#include "core/image.h"
#include "core/math.h"
#include "core/parallel.h"
#include "core/stats.h"
#include "core/view.h"
#include "metrics/heatmap.h"
#include "metrics/image_compare.h"
#include "render/frame.h"
#include "render/image_io.h"
#include "render/shading.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/load_mesh.h"
#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "shadows/technique.h"
