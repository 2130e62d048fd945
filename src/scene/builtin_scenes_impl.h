#pragma once
// The built-in scenes' builders (not finalized; builtinScene() names and finalizes them).
#include "scene/scene.h"

namespace penumbra {

Scene makeSpheresScene();     // builtin_simple_scenes.cpp
Scene makeColumnsScene();     // builtin_simple_scenes.cpp
Scene makeMultilightScene();  // builtin_simple_scenes.cpp
Scene makeFractalScene();     // builtin_fractal_scene.cpp
Scene makeYear2002Scene();    // builtin_year2002_scene.cpp

}  // namespace penumbra
