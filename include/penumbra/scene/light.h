#pragma once
#include <memory>
#include <string>
#include <vector>

#include <penumbra/core/math.h>

namespace penumbra {

// What the light's area is. The penumbra-wedge papers and the exact soft shadow volumes use a
// sphere; the 2003 soft shadow volumes (Assarsson and Akenine-Moller) use a rectangle, and
// Funk's 2004 report a circle (`coverage` takes all three, as do `exact`, `heckbert-herf` and
// the oracle). Visibility is always the fraction of the light's area (a sphere: of the disk it
// shows the point) that the point sees, with no cosine weighting, as in the papers.
enum class LightShape {
  Sphere,     // centre and radius; seen from a point, the disk its tangent cone cuts out
  Disk,       // centre, radius and unit normal; lights both sides
  Rectangle,  // centre and two orthogonal full edge vectors: corners centre +- u/2 +- v/2
};
std::string lightShapeName(LightShape shape);  // "sphere", "disk", "rectangle"

// What a textured rectangle light emits over its area (issue 9 item 3; the 2003 soft shadow
// volumes' textured lights): linear RGB, piecewise constant over a grid of cells. Texel (i, j)
// covers the part of the rectangle with s in [i / width, (i + 1) / width) along edge_u and
// t in [j / height, (j + 1) / height) along edge_v, (s, t) = (0, 0) at centre - u/2 - v/2; an
// image's row 0 is t's first row. A point's visibility of such a light is per channel: the
// texture-weighted fraction of the light it sees, sum over seen area of texel / sum over all.
struct LightTexture {
  int width = 0, height = 0;  // 1..kMaxLightTextureCells each
  std::vector<vec3> texels;   // row-major, width * height, finite and >= 0
  vec3 mean{0.0f};            // the average texel (lightRadiance)
  vec3 at(vec2 st) const;     // the texel holding (s, t) in [0, 1]^2 (edges clamped)
};
// Textures are box-filtered down to at most this many cells a side (makeLightTexture): the
// exact coverage walks the cells an edge crosses.
inline constexpr int kMaxLightTextureCells = 32;
// A texture from an image's texels (linear RGB, row-major): box-filtered by area to at most
// kMaxLightTextureCells a side. Throws penumbra::Error naming `what` for an empty image, texels
// that are not finite or negative, or a texture that emits nothing.
std::shared_ptr<const LightTexture> makeLightTexture(int width, int height,
                                                     const std::vector<vec3>& texels,
                                                     const std::string& what);

// A light. radius 0 is a point light and every technique must then give exactly the
// hard-shadow result. For a disk `radius` is the disk's; for a rectangle it is the radius of
// its bounding sphere (half the diagonal), which rectangleLight keeps consistent and
// checkLightShape checks: techniques that bound work by a sphere (culling, facing-away tests)
// read it whatever the shape.
struct Light {
  vec3 center{0.0f, 10.0f, 0.0f};
  float radius = 0.0f;      // world units, >= 0
  vec3 color{1.0f};         // linear RGB
  float intensity = 1.0f;   // scales color; no distance falloff (as in the papers' images)
  LightShape shape = LightShape::Sphere;
  vec3 normal{0.0f, -1.0f, 0.0f};  // Disk: unit normal
  vec3 edge_u{0.0f}, edge_v{0.0f};  // Rectangle: full edge vectors, orthogonal
  // Rectangle only: its emission over its area; null emits `color` uniformly.
  std::shared_ptr<const LightTexture> texture{};
};

// What the fully visible light sends a point, before the surface's response: color x intensity,
// times the texture's mean for a textured light.
vec3 lightRadiance(const Light& light);

Light diskLight(const vec3& center, const vec3& normal, float radius);
// The rectangle with corners center +- u/2 +- v/2; radius = |u + v| / 2.
Light rectangleLight(const vec3& center, const vec3& edge_u, const vec3& edge_v);

// Area of the light's emitting shape (a sphere's: pi r^2, the disk it shows a point).
double lightArea(const Light& light);

// Throws penumbra::Error naming what is wrong: a non-finite centre or radius, a negative
// radius, a disk normal that is not unit length, rectangle edges that are zero, not finite or
// not orthogonal, a rectangle radius that is not half its diagonal, or a texture on a light that
// is not a rectangle.
void checkLightShape(const Light& light);

// Throws penumbra::Error "<technique> supports only spherical lights, not a <shape> light"
// for a non-sphere light: the techniques built on a sphere (wedges, shadow maps) call it
// where they render, rather than treat another shape as a sphere.
void requireSphereLight(const Light& light, const std::string& technique);

}  // namespace penumbra
