#pragma once
// Which axis of a mesh file points up. Penumbra's world is y-up (README "Conventions"); scans
// and CAD exports are often z-up and would lie on their side.
#include <string>

#include <penumbra/core/math.h>

namespace penumbra {

enum class UpAxis { X, Y, Z };

// "x", "y" or "z"; throws penumbra::Error naming the text otherwise.
UpAxis parseUpAxis(const std::string& text);
// The rotation that turns `up` into +y: a rotation, never a mirror, so triangles keep their
// winding. +z up: (x, y, z) -> (x, z, -y); +x up: (x, y, z) -> (-y, x, z).
mat4 upAxisToY(UpAxis up);

}  // namespace penumbra
