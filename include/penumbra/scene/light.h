#pragma once
#include <string>

#include <penumbra/core/math.h>

namespace penumbra {

// What the light's area is. The penumbra-wedge papers and the exact soft shadow volumes use a
// sphere; the 2003 soft shadow volumes (Assarsson and Akenine-Moller) use a rectangle, and
// Funk's 2004 report a circle (`coverage` takes all three, as do `heckbert-herf` and the
// oracle). Visibility is always the fraction of the light's area (a sphere: of the disk it
// shows the point) that the point sees, with no cosine weighting, as in the papers.
enum class LightShape {
  Sphere,     // centre and radius; seen from a point, the disk its tangent cone cuts out
  Disk,       // centre, radius and unit normal; lights both sides
  Rectangle,  // centre and two orthogonal full edge vectors: corners centre +- u/2 +- v/2
};
std::string lightShapeName(LightShape shape);  // "sphere", "disk", "rectangle"

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
};

Light diskLight(const vec3& center, const vec3& normal, float radius);
// The rectangle with corners center +- u/2 +- v/2; radius = |u + v| / 2.
Light rectangleLight(const vec3& center, const vec3& edge_u, const vec3& edge_v);

// Area of the light's emitting shape (a sphere's: pi r^2, the disk it shows a point).
double lightArea(const Light& light);

// Throws penumbra::Error naming what is wrong: a non-finite centre or radius, a negative
// radius, a disk normal that is not unit length, rectangle edges that are zero, not finite or
// not orthogonal, or a rectangle radius that is not half its diagonal.
void checkLightShape(const Light& light);

// Throws penumbra::Error "<technique> supports only spherical lights, not a <shape> light"
// for a non-sphere light: the techniques built on a sphere (wedges, exact, shadow maps) call it
// where they render, rather than treat another shape as a sphere.
void requireSphereLight(const Light& light, const std::string& technique);

}  // namespace penumbra
