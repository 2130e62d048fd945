#include "shadows/wedge/light_wedges.h"

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "core/parallel.h"
#include "core/pseudo_angle.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/stages/silhouettes/edge_on_sheet.h"
#include "shadows/wedge/wedge_light_reach.h"

namespace penumbra {
namespace {

// A polygon corner: its clip-space vertex and a finite world-space stand-in used only to decide
// which way the polygon is wound (points at infinity stand in at a large distance).
struct Corner {
  uint32_t clip;
  dvec3 world;
};

dvec3 newellNormal(const std::vector<Corner>& poly) {
  dvec3 n(0.0);
  for (size_t i = 0; i < poly.size(); ++i) {
    const dvec3& p = poly[i].world;
    const dvec3& q = poly[(i + 1) % poly.size()].world;
    n += dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  return n;
}

class LightWedgesBuilder {
 public:
  LightWedgesBuilder(LightWedges& wedges, const View& view) : f_(wedges), view_(view) {}

  uint32_t vertex(const vec4& homogeneous_world) {
    return f_.triangles.addVertex(view_.toClip(homogeneous_world));
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c, const WedgeRole& role) {
    f_.roles.push_back(role);
    f_.triangles.add(a, b, c, int32_t(f_.roles.size() - 1), role.zfail ? kZFail : 0);
  }
  // Adds a convex polygon wound so that its normal points along `outward`, as a fan.
  void polygon(std::vector<Corner> poly, const dvec3& outward, const WedgeRole& role) {
    if (glm::dot(newellNormal(poly), outward) < 0.0) std::reverse(poly.begin(), poly.end());
    for (size_t k = 1; k + 1 < poly.size(); ++k)
      triangle(poly[0].clip, poly[k].clip, poly[k + 1].clip, role);
  }

 private:
  LightWedges& f_;
  const View& view_;
};

WedgeRole withFace(WedgeRole role, WedgeFace face) {
  role.face = face;
  return role;
}

// The wedge polyhedron that the penumbra passes rasterize: the points inside all four planes
// (2002 paper, section 6: a point "is inserted into all plane equations to determine whether
// the point is inside the wedge"), in homogeneous coordinates, w >= 0, so that an unbounded
// wedge ends on the plane at infinity as the shadow volume does. Where the side planes cross
// (section 4.1, Figure 6) the four planes alone close the wedge at the line where they meet;
// the wedge builder's bottom-plane cut (Wedge::finite) is not used, because the region
// between the cut and that line is then covered by no wedge at all and reads as umbra: the
// shadows of thin parts (the bunny's ears) end in black bars, and bunny-lowres's penumbra
// error against the oracle grows (docs/wedge-accuracy.md).
//
// Vertices are the feasible intersections of three of the five constraints (the four planes
// and w = 0); faces are the vertices on each constraint, ordered around it. Bit k of `on`: the
// vertex lies on constraint k (WedgeFace: kFront..kRight, kFar for w = 0).
struct HullVertex {
  dvec4 h;         // unit length, w >= 0; w == 0: a direction
  uint8_t on = 0;
  dvec3 proxy{0};  // finite stand-in, for ordering and winding only
};

struct WedgeHull {
  std::vector<HullVertex> vertices;
  std::vector<std::vector<uint32_t>> faces;  // indexed by WedgeFace, empty when absent
  dvec3 far_outward{0.0};  // outward normal of the face at infinity (its mean direction)
  bool valid = false;
};

double det3(const dvec3& a, const dvec3& b, const dvec3& c) {
  return glm::dot(a, glm::cross(b, c));
}

// The vector orthogonal to a, b and c in R^4 (cofactor expansion of the 4x4 determinant).
dvec4 cross4(const dvec4& a, const dvec4& b, const dvec4& c) {
  return dvec4(det3(dvec3(a.y, a.z, a.w), dvec3(b.y, b.z, b.w), dvec3(c.y, c.z, c.w)),
               -det3(dvec3(a.x, a.z, a.w), dvec3(b.x, b.z, b.w), dvec3(c.x, c.z, c.w)),
               det3(dvec3(a.x, a.y, a.w), dvec3(b.x, b.y, b.w), dvec3(c.x, c.y, c.w)),
               -det3(dvec3(a.x, a.y, a.z), dvec3(b.x, b.y, b.z), dvec3(c.x, c.y, c.z)));
}

// The wedge's planes and the plane at infinity as the hull's five constraints (indexed by
// WedgeFace), each a homogeneous vector c with c . (p, 1) >= 0 inside.
struct WedgeConstraints {
  explicit WedgeConstraints(const Wedge& w)
      : planes{&w.front, &w.back, &w.left, &w.right},
        extent(glm::length(w.a) + glm::length(w.b - w.a)) {
    for (int k = 0; k < 4; ++k) constraint[k] = dvec4(planes[k]->n, planes[k]->d);
    constraint[kFar] = dvec4(0.0, 0.0, 0.0, 1.0);
  }
  const Plane* planes[4];
  dvec4 constraint[5];
  // Plane values are distances (unit normals); rounding in them grows with the coordinates.
  double extent;
};

// Adds the feasible point or direction x (unit length), the meeting point of the constraints
// `triple`, to the hull's vertices: its sign fitted, the constraints it lies on set, merged
// with a vertex found before from another triple.
void addHullVertex(const Wedge& w, const WedgeConstraints& wc, const dvec4& x, uint8_t triple,
                   bool direction, WedgeHull& hull) {
  const auto tolerance = [&](const dvec3& p) {
    return 1e-9 * (wc.extent + glm::length(p - w.a));
  };
  constexpr double kDirectionTolerance = 1e-9;
  for (const double sign : {1.0, -1.0}) {
    dvec4 h = sign * x;
    if (direction) {
      h.w = 0.0;
      h /= glm::length(h);
    } else if (h.w < 0.0) {
      continue;
    }
    const dvec3 p = direction ? dvec3(h) : dvec3(h) / h.w;
    uint8_t on = uint8_t(triple | (direction ? 1u << kFar : 0u));
    bool feasible = true;
    for (int m = 0; m < 4 && feasible; ++m) {
      const double value = direction ? glm::dot(wc.planes[m]->n, p) : wc.planes[m]->eval(p);
      const double tol = direction ? kDirectionTolerance : tolerance(p);
      feasible = value >= -tol;
      if (std::fabs(value) <= tol) on = uint8_t(on | (1u << m));
    }
    if (!feasible) continue;
    bool merged = false;
    for (HullVertex& v : hull.vertices) {
      if (glm::length(v.h - h) <= 1e-12) {
        v.on = uint8_t(v.on | on);
        merged = true;
      }
    }
    if (!merged) hull.vertices.push_back(HullVertex{h, on, p});
    return;
  }
}

// The hull's vertices (section 6: the points inside all the wedge's planes): the feasible
// intersections of three of the five constraints.
void findHullVertices(const Wedge& w, const WedgeConstraints& wc, WedgeHull& hull) {
  // A gap wedge (wedge_gap.h, a == b) is a cone: all four planes pass through its apex, which
  // is then its only finite vertex. Solving for it from four different triples gives four
  // copies that differ by more than the merge distance (front and back are nearly parallel),
  // so the apex is taken as is and only the directions (triples with w = 0) are solved for.
  const bool cone = w.a == w.b;
  if (cone)
    hull.vertices.push_back(HullVertex{glm::normalize(dvec4(w.a, 1.0)),
                                       uint8_t((1u << kFront) | (1u << kBack) | (1u << kLeft) |
                                               (1u << kRight)),
                                       w.a});
  const dvec4* constraint = wc.constraint;
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j)
      for (int k = j + 1; k < 5; ++k) {
        if (cone && k != kFar) continue;
        dvec4 x = cross4(constraint[i], constraint[j], constraint[k]);
        const double len = glm::length(x);
        const double scale = glm::length(constraint[i]) * glm::length(constraint[j]) *
                             glm::length(constraint[k]);
        if (!(len > 1e-12 * scale)) continue;  // the three constraints share a line
        x /= len;
        const uint8_t triple = uint8_t((1u << i) | (1u << j) | (1u << k));
        // A point (w > 0) or a direction (w = 0; also a point so far away that its w is
        // rounding noise): the sign of a direction is free, the one that fits is taken.
        const bool direction = k == kFar || std::fabs(x.w) <= 1e-12 * glm::length(dvec3(x));
        addHullVertex(w, wc, x, triple, direction, hull);
      }
}

// Finite stand-ins for the hull's directions, far beyond every finite vertex; returns the
// directions' sum (the mean direction of the face at infinity).
dvec3 placeHullProxies(const Wedge& w, WedgeHull& hull) {
  double far = std::max(1.0, glm::length(w.b - w.a));
  for (const HullVertex& v : hull.vertices)
    if (v.h.w != 0.0) far = std::max(far, glm::length(v.proxy - w.a));
  far *= 1e3;
  dvec3 mean_direction(0.0);
  for (HullVertex& v : hull.vertices) {
    if (v.h.w == 0.0) {
      mean_direction += v.proxy;
      v.proxy = w.a + far * v.proxy;
    }
  }
  return mean_direction;
}

// The vertices on constraint k ordered around it (by pseudo-angle about their centre, in the
// plane of normal n); a face of fewer than 3 is cleared.
void orderHullFace(const WedgeHull& hull, int k, const dvec3& n, std::vector<uint32_t>& face) {
  for (uint32_t v = 0; v < hull.vertices.size(); ++v)
    if (hull.vertices[v].on & (1u << k)) face.push_back(v);
  if (face.size() < 3) {
    face.clear();
    return;
  }
  dvec3 centre(0.0);
  for (uint32_t v : face) centre += hull.vertices[v].proxy;
  centre /= double(face.size());
  const dvec3 axis = std::fabs(n.x) < 0.6 * glm::length(n) ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  const dvec3 u = glm::normalize(glm::cross(n, axis));
  const dvec3 t = glm::cross(n, u);
  std::vector<std::pair<double, uint32_t>> angle;
  for (uint32_t v : face) {
    const dvec3 d = hull.vertices[v].proxy - centre;
    angle.emplace_back(pseudoAngle(glm::dot(d, u), glm::dot(d, t)), v);
  }
  std::sort(angle.begin(), angle.end());
  for (size_t i = 0; i < face.size(); ++i) face[i] = angle[i].second;
}

WedgeHull wedgeHull(const Wedge& w) {
  const WedgeConstraints wc(w);
  WedgeHull hull;
  findHullVertices(w, wc, hull);
  const dvec3 mean_direction = placeHullProxies(w, hull);
  hull.far_outward = mean_direction;
  hull.faces.resize(5);
  size_t edges2 = 0, face_count = 0;
  for (int k = 0; k < 5; ++k) {
    std::vector<uint32_t>& face = hull.faces[size_t(k)];
    orderHullFace(hull, k, k == kFar ? mean_direction : wc.planes[k]->n, face);
    if (face.empty()) continue;
    edges2 += face.size();
    ++face_count;
  }
  // A convex polyhedron (a ball, its face at infinity included) has V - E + F = 2, and each of
  // its vertices is on three faces at least; anything else is a degenerate wedge.
  bool corners = true;
  for (const HullVertex& v : hull.vertices) {
    int faces_on = 0;
    for (int k = 0; k < 5; ++k)
      faces_on += (v.on & (1u << k)) && !hull.faces[size_t(k)].empty();
    corners = corners && faces_on >= 3;
  }
  hull.valid = corners && edges2 % 2 == 0 && face_count >= 4 &&
               int64_t(hull.vertices.size()) - int64_t(edges2 / 2) + int64_t(face_count) == 2;
  return hull;
}

// The front face is a, b and the two front directions: exactly the unit edge's umbra quad.
bool frontIsQuad(const WedgeHull& hull) {
  const std::vector<uint32_t>& face = hull.faces[kFront];
  if (face.size() != 4) return false;
  int points = 0, directions = 0;
  for (const uint32_t v : face) {
    const HullVertex& hv = hull.vertices[v];
    const bool left = hv.on & (1u << kLeft), right = hv.on & (1u << kRight);
    if (left == right) return false;
    (hv.h.w != 0.0 ? points : directions) += 1;
    if (hv.h.w != 0.0 && !(hv.on & (1u << kBack))) return false;
  }
  return points == 2 && directions == 2;
}

// A mesh's world-space wedges and their hulls and screen planes: everything of the wedges that
// does not depend on the other meshes, so meshes are prepared in parallel (a scene of many small
// casters, like columns, has too few wedges per mesh to split one mesh's work).
struct MeshWedges {
  CasterVolume volume;
  // A silhouette edge the light reaches: no wedges are built, the light is refused.
  std::optional<EdgeInsideLight> inside_light;
  WedgeSet ws;
  std::vector<WedgeHull> hulls;      // per wedge of ws.wedges, then ws.gap_wedges
  std::vector<ScreenWedge> screens;  // same order; valid where the hull is

  size_t wedgeCount() const { return ws.wedges.size() + ws.gap_wedges.size(); }
  // The edge wedges, then the gap wedges at split vertices (wedge_gap.h). A gap wedge's front
  // face is a triangle (the vertex and two directions), never a quad, so its connector umbra
  // quad is counted as a plain umbra polygon and the front face is drawn as a penumbra face of
  // its own, as for crossing front rays.
  const Wedge& wedge(size_t i) const {
    return i < ws.wedges.size() ? ws.wedges[i] : ws.gap_wedges[i - ws.wedges.size()];
  }
};

MeshWedges prepareMesh(const LightWedgesOptions& options, const Scene& scene, size_t m,
                       const Light& light, const View& view, const EyeBuffers& eye,
                       const ScreenProjection& projection) {
  const Mesh& mesh = scene.meshes[m];
  const bool soft = light.radius > 0.0f;
  MeshWedges p;
  // Open meshes cast one-sided where they are consistently oriented (silhouette.h,
  // SolidWithHoles). Two-sided, a silhouette edge where both sheets of such a mesh meet has
  // multiplicity 2: two coincident wedges and an umbra count of 2, so the LI is 255 (2 v - 1)
  // and the inner half of the penumbra clamps to black (the overlap the 2002 paper names as a
  // limitation, section 8: README, "Known limitation: overlapping wedges"). With
  // a zero radius there is no penumbra, and the umbra must be the hard shadow volume bit for
  // bit (light_wedges.h), so the hard volume's casters are kept. The soft volume lies within
  // distance r of the hard volume from the centre, so growing the caster's box by r keeps the
  // near-plane test conservative (caster_volume.h).
  const CasterPolicy policy = !soft                 ? CasterPolicy::Auto
                              : options.other_facing_meshes != nullptr
                                  ? CasterPolicy::SolidWithHolesOtherFacing
                                                     : CasterPolicy::SolidWithHoles;
  p.volume = casterVolume(scene, m, eye, light.center, view, options.volume_mode, policy,
                          light.radius);
  if (options.edge_on_facing != 0)
    p.volume.silhouette = edgeOnSheet(mesh, scene.adjacency[m], light, p.volume.silhouette,
                                      options.edge_on_facing);
  p.inside_light = edgeInsideLight(mesh, p.volume.silhouette, light);
  if (p.inside_light) return p;
  p.ws = buildWedges(mesh, p.volume.silhouette, light);
  const size_t n_wedges = p.wedgeCount();
  p.hulls.resize(n_wedges);
  p.screens.resize(n_wedges);
  if (!soft) return p;
  // Hulls and screen-space planes are independent per wedge (most of the construction time:
  // 19k wedges on fractal), so they are solved in parallel too; the wedges are numbered
  // in order, so it does not depend on the thread count.
  constexpr size_t kChunk = 64;
  parallelFor((n_wedges + kChunk - 1) / kChunk, [&](size_t c) {
    for (size_t i = c * kChunk; i < std::min(n_wedges, (c + 1) * kChunk); ++i) {
      const Wedge& w = p.wedge(i);
      if (w.flat) continue;
      p.hulls[i] = wedgeHull(w);
      if (!p.hulls[i].valid) continue;
      std::vector<dvec4> corners;
      for (const HullVertex& v : p.hulls[i].vertices) corners.push_back(v.h);
      p.screens[i] = toScreenWedge(w, corners, projection, options.smooth_falloff);
      p.screens[i].front_quad = i < p.ws.wedges.size() && frontIsQuad(p.hulls[i]);
    }
  });
  return p;
}

// A silhouette edge the light reaches refuses the light: the nearest such edge (the first
// mesh's on a tie, whatever the thread count) is named, its distance being the largest radius
// the light's wedges could take.
void refuseEdgeInsideLight(const Scene& scene, const Light& light,
                           const std::vector<MeshWedges>& prepared) {
  size_t reached = scene.meshes.size();
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (prepared[m].inside_light &&
        (reached == scene.meshes.size() ||
         prepared[m].inside_light->distance < prepared[reached].inside_light->distance))
      reached = m;
  if (reached < scene.meshes.size())
    throw Error(
        edgeInsideLightMessage(scene.meshes[reached], light, *prepared[reached].inside_light));
}

// A mesh's valid wedges appended to the light's, numbered globally (global_wedge, per wedge of
// the mesh); front_face_of marks the umbra quads that are also the front face of a wedge: the
// unit edge's quad, when the front rays do not cross (the front face is then a, b and the two
// front directions).
void numberMeshWedges(const MeshWedges& p, LightWedges& f, std::vector<int32_t>& front_face_of,
                      std::vector<int32_t>& global_wedge) {
  int32_t next = int32_t(f.wedges.size());
  for (size_t i = 0; i < p.wedgeCount(); ++i) {
    const Wedge& w = p.wedge(i);
    if (w.flat) continue;
    if (!p.hulls[i].valid) {
      ++f.degenerate_wedges;
      continue;
    }
    global_wedge[i] = next++;
    f.wedges.push_back(w);
    f.screen.push_back(p.screens[i]);
    if (p.screens[i].front_quad) front_face_of[w.unit_edge] = global_wedge[i];
  }
}

// The umbra quads (2002 paper, section 4: the hard shadow volume of the front planes), in the hard
// shadow volume's vertex order and sign convention (shadows/stages/stencil/shadow_stencil.cpp: (v1,
// v0, v0', v1') with v0 < v1 and a signed weight), with z-fail's skirts; their vertices at infinity
// kept in inf_a and inf_b (per umbra quad) for the wedges' front faces.
void appendUmbraQuads(const MeshWedges& p, const std::vector<int32_t>& front_face_of,
                      LightWedgesBuilder& out, std::vector<uint32_t>& inf_a,
                      std::vector<uint32_t>& inf_b) {
  const WedgeSet& ws = p.ws;
  const bool zfail = p.volume.zfail;
  const uint32_t base = p.volume.finite, infinite = p.volume.infinite;
  for (size_t k = 0; k < ws.umbra.size(); ++k) {
    const UmbraQuad& q = ws.umbra[k];
    inf_a[k] = out.vertex(vec4(q.inf_a, 0.0f));
    inf_b[k] = out.vertex(vec4(q.inf_b, 0.0f));
    const bool forward = q.va < q.vb;
    const uint32_t v0 = forward ? q.va : q.vb, v1 = forward ? q.vb : q.va;
    const uint32_t i0 = forward ? inf_a[k] : inf_b[k], i1 = forward ? inf_b[k] : inf_a[k];
    const int32_t weight = forward ? 1 : -1;
    WedgeRole role;
    role.umbra_weight = weight;
    role.wedge = front_face_of[k];
    role.face_sign = int8_t(weight);
    role.face = role.wedge != kNoWedge ? kFront : -1;
    role.zfail = zfail;
    out.triangle(base + v1, base + v0, i0, role);
    out.triangle(base + v1, i0, i1, role);
    if (zfail) {
      // Skirt at infinity between the hard volume's directions and the front-plane ones:
      // light caps + front quads + skirts + hard dark caps form a closed surface (with r = 0
      // the skirts have no area and this is the hard shadow volume).
      WedgeRole skirt;
      skirt.umbra_weight = weight;
      skirt.zfail = true;
      out.triangle(i0, infinite + v0, infinite + v1, skirt);
      out.triangle(i0, infinite + v1, i1, skirt);
    }
  }
}

// The other faces of one wedge polyhedron (the penumbra footprint; section 6's four planes and
// the plane at infinity). Its corners on the occluder are the mesh's own vertices and, when
// the front face is the umbra quad, its front directions are the quad's: shared clip vertices
// keep the faces watertight.
void appendWedgeFaces(const MeshWedges& p, size_t i, int32_t global, bool quad,
                      const std::vector<uint32_t>& inf_a, const std::vector<uint32_t>& inf_b,
                      LightWedgesBuilder& out) {
  const Wedge& w = p.wedge(i);
  const WedgeHull& hull = p.hulls[i];
  const uint32_t base = p.volume.finite;
  const auto on = [](const HullVertex& v, std::initializer_list<int> faces) {
    for (const int k : faces)
      if (!(v.on & (1u << k))) return false;
    return true;
  };
  std::vector<uint32_t> clip(hull.vertices.size());
  for (size_t v = 0; v < hull.vertices.size(); ++v) {
    const HullVertex& hv = hull.vertices[v];
    const bool point = hv.h.w != 0.0;
    if (point && on(hv, {kFront, kBack, kLeft})) {
      clip[v] = base + w.va;
    } else if (point && on(hv, {kFront, kBack, kRight})) {
      clip[v] = base + w.vb;
    } else if (quad && !point && on(hv, {kFront, kLeft})) {
      clip[v] = inf_a[w.unit_edge];
    } else if (quad && !point && on(hv, {kFront, kRight})) {
      clip[v] = inf_b[w.unit_edge];
    } else {
      clip[v] = out.vertex(vec4(hv.h));
    }
  }
  WedgeRole role;
  role.wedge = global;
  role.zfail = p.volume.zfail;
  const Plane* planes[4] = {&w.front, &w.back, &w.left, &w.right};
  for (int k = 0; k < 5; ++k) {
    const std::vector<uint32_t>& face = hull.faces[size_t(k)];
    if (face.empty() || (k == kFront && quad)) continue;
    std::vector<Corner> corners;
    for (const uint32_t v : face) corners.push_back(Corner{clip[v], hull.vertices[v].proxy});
    out.polygon(corners, k == kFar ? hull.far_outward : -planes[k]->n,
                withFace(role, WedgeFace(k)));
  }
}

// One mesh's part of the light's wedges: its extruded vertices, umbra quads, caps (z-fail)
// and wedge faces.
void appendMeshWedges(const Mesh& mesh, MeshWedges& p, const Light& light, const View& view,
                      LightWedges& f, LightWedgesBuilder& out) {
  const WedgeSet& ws = p.ws;
  f.silhouette_edges += p.volume.silhouette.edges.size();
  f.junction_vertices += ws.junction_vertices;
  appendExtrudedVertices(mesh, light.center, view, p.volume, f.triangles);
  const size_t n_wedges = p.wedgeCount();
  std::vector<int32_t> front_face_of(ws.umbra.size(), kNoWedge);
  std::vector<int32_t> global_wedge(n_wedges, kNoWedge);
  if (light.radius > 0.0f) numberMeshWedges(p, f, front_face_of, global_wedge);
  std::vector<uint32_t> inf_a(ws.umbra.size()), inf_b(ws.umbra.size());
  appendUmbraQuads(p, front_face_of, out, inf_a, inf_b);
  if (p.volume.zfail) {
    // Light caps (the casters themselves) and dark caps at infinity (caster_volume.h).
    forEachCap(mesh, p.volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
      WedgeRole cap;
      cap.umbra_weight = weight;
      cap.zfail = true;
      out.triangle(a, b, c, cap);
    });
  }
  for (size_t i = 0; i < n_wedges; ++i) {
    if (global_wedge[i] == kNoWedge) continue;
    appendWedgeFaces(p, i, global_wedge[i], f.screen[size_t(global_wedge[i])].front_quad, inf_a,
                     inf_b, out);
  }
}

}  // namespace

LightWedges buildLightWedges(const LightWedgesOptions& options, const Scene& scene,
                           const Light& light, const View& view, const EyeBuffers& eye) {
  LightWedges f;
  f.triangles = ClipTriangles(eye.clip_vertices);
  LightWedgesBuilder out(f, view);
  const ScreenProjection projection = screenProjection(view);
  std::vector<MeshWedges> prepared(scene.meshes.size());
  // The other facing's pass draws only the meshes it was given.
  auto casts = [&](size_t m) {
    return (options.other_facing_meshes == nullptr || (*options.other_facing_meshes)[m] != 0) &&
           (options.caster_culling == nullptr || options.caster_culling->mayShadow(m));
  };
  parallelFor(scene.meshes.size(), [&](size_t m) {
    if (casts(m)) prepared[m] = prepareMesh(options, scene, m, light, view, eye, projection);
  });
  refuseEdgeInsideLight(scene, light, prepared);
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (casts(m)) appendMeshWedges(scene.meshes[m], prepared[m], light, view, f, out);
  return f;
}

}  // namespace penumbra
