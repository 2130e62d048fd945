#pragma once
// The built-in scenes' builders (not finalized; builtinScene() names and finalizes them).
#include "scene/scene.h"

namespace penumbra {

Scene makeSpheresScene();     // builtin_simple_scenes.cpp
Scene makeColumnsScene();     // builtin_simple_scenes.cpp
Scene makeMultilightScene();  // builtin_simple_scenes.cpp
Scene makeFractalScene();     // builtin_fractal_scene.cpp
Scene makeYear2002Scene();    // builtin_year2002_scene.cpp

// "city:N": N x N blocks (builtin_city_scene.cpp), about 32,000 triangles each; "city" is
// kDefaultCityBlocks (2.0 M triangles): the size today's pipeline, which rasterises every
// triangle every frame, renders in seconds. city:20 is issue 32's 10 M triangle city (12.9 M),
// city:64 holds 130 M (docs/scene-format.md, "The built-in city", has the measurements).
constexpr int kDefaultCityBlocks = 8;
constexpr int kTenMillionCityBlocks = 20;
constexpr int kMaxCityBlocks = 64;
Scene makeCityScene(int blocks);

// "interior:N": a hall of N x N bays (builtin_interior_scene.cpp); "interior" is
// kDefaultInteriorBays.
constexpr int kDefaultInteriorBays = 4;
constexpr int kMaxInteriorBays = 64;
Scene makeInteriorScene(int bays);

}  // namespace penumbra
