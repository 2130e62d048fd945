#include "shadows/wedge/wedge_frame.h"

#include <algorithm>

#include "core/parallel.h"
#include "shadows/silhouette.h"
#include "shadows/volume/volume_mode.h"

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

class FrameBuilder {
 public:
  FrameBuilder(WedgeFrame& frame, const View& view) : f_(frame), view_(view) {}

  uint32_t vertex(const vec4& homogeneous_world) {
    f_.triangles.clip.push_back(view_.toClip(homogeneous_world));
    return uint32_t(f_.triangles.clip.size() - 1);
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
  WedgeFrame& f_;
  const View& view_;
};

WedgeRole withFace(WedgeRole role, WedgeFace face) {
  role.face = face;
  return role;
}

Bounds3 inflated(Bounds3 b, float r) {
  if (b.empty()) return b;
  b.min -= vec3(r);
  b.max += vec3(r);
  return b;
}

}  // namespace

WedgeFrame buildWedgeFrame(const TechniqueOptions& options, const Scene& scene,
                           const Light& light, const View& view) {
  WedgeFrame f;
  FrameBuilder out(f, view);
  const bool soft = light.radius > 0.0f;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const Silhouette silhouette = findSilhouette(mesh, scene.adjacency[m], light.center);
    f.silhouette_edges += silhouette.edges.size();
    WedgeOptions wedge_options;
    wedge_options.acute_vertex_wedges = options.acute_wedges;
    const WedgeSet ws = buildWedges(mesh, silhouette, light, wedge_options);
    f.junction_vertices += ws.junction_vertices;
    // The soft volume lies within distance r of the hard volume from the centre, so inflating
    // the caster's box by r keeps the near-plane test conservative (volume_mode.h). The 2002
    // algorithm predates z-fail for wedges (its section 8) and always counts from the eye.
    const bool zfail =
        options.kind != TechniqueKind::Wedge2002 &&
        (options.volume_mode == VolumeMode::ZFail ||
         (options.volume_mode == VolumeMode::Auto &&
          mayContainNearPlane(view, light.center, inflated(mesh.bounds(), light.radius))));

    const size_t n = mesh.positions.size();
    const uint32_t base = uint32_t(f.triangles.clip.size());
    f.triangles.clip.resize(base + 2 * n);
    parallelFor((n + 4095) / 4096, [&](size_t chunk) {
      for (size_t i = chunk * 4096; i < std::min(n, (chunk + 1) * 4096); ++i) {
        // The same transforms as the eye pass and the hard shadow volume (volume_geometry.cpp):
        // caps and the zero-radius umbra must land on bit-identical clip coordinates.
        f.triangles.clip[base + i] = view.toClip(vec4(mesh.positions[i], 1.0f));
        f.triangles.clip[base + n + i] = view.toClip(vec4(mesh.positions[i] - light.center, 0.0f));
      }
    });
    auto finite = [&](uint32_t v) { return base + v; };
    auto hard_infinity = [&](uint32_t v) { return uint32_t(base + n + v); };

    // Which umbra quads are also the front face of an (unbounded) wedge.
    const int32_t wedge_base = int32_t(f.wedges.size());
    std::vector<int32_t> front_face_of(ws.umbra.size(), kNoWedge);
    std::vector<int32_t> global_wedge(ws.wedges.size(), kNoWedge);
    if (soft) {
      int32_t next = wedge_base;
      for (size_t i = 0; i < ws.wedges.size(); ++i) {
        const Wedge& w = ws.wedges[i];
        if (w.flat) continue;
        global_wedge[i] = next++;
        f.wedges.push_back(w);
        f.screen.push_back(toScreenWedge(w, view, options.smooth_falloff));
        if (!w.finite) front_face_of[w.unit_edge] = global_wedge[i];
      }
    }

    // Umbra quads, in the hard shadow volume's vertex order and sign convention
    // (volume_geometry.cpp: (v1, v0, v0', v1') with v0 < v1 and a signed weight).
    std::vector<uint32_t> inf_a(ws.umbra.size()), inf_b(ws.umbra.size());
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
      out.triangle(finite(v1), finite(v0), i0, role);
      out.triangle(finite(v1), i0, i1, role);
      if (zfail) {
        // Skirt at infinity between the hard volume's directions and the front-plane ones:
        // light caps + front quads + skirts + hard dark caps form a closed surface (with r = 0
        // the skirts have no area and this is the hard shadow volume).
        WedgeRole skirt;
        skirt.umbra_weight = weight;
        skirt.zfail = true;
        out.triangle(i0, hard_infinity(v0), hard_infinity(v1), skirt);
        out.triangle(i0, hard_infinity(v1), i1, skirt);
      }
    }
    if (zfail) {
      for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const int8_t o = silhouette.orientation[t];
        if (o == 0) continue;
        const uint32_t a = mesh.indices[t * 3], b = mesh.indices[t * 3 + 1], c = mesh.indices[t * 3 + 2];
        WedgeRole cap;
        cap.umbra_weight = o;  // light cap: the caster itself, in its own vertex order
        cap.zfail = true;
        out.triangle(finite(a), finite(b), finite(c), cap);
        cap.umbra_weight = -o;  // dark cap at infinity, facing away
        out.triangle(hard_infinity(a), hard_infinity(b), hard_infinity(c), cap);
      }
    }

    // The other faces of every wedge polyhedron (the penumbra footprint).
    for (size_t i = 0; i < ws.wedges.size(); ++i) {
      if (global_wedge[i] == kNoWedge) continue;
      const Wedge& w = ws.wedges[i];
      WedgeRole role;
      role.wedge = global_wedge[i];
      role.zfail = zfail;
      const Corner a{finite(w.va), w.a}, b{finite(w.vb), w.b};
      const double scale = std::max(1.0, 1e3 * glm::length(w.b - w.a));
      if (!w.finite) {
        const UmbraQuad& q = ws.umbra[w.unit_edge];
        const Corner fl{inf_a[w.unit_edge], w.a + dvec3(q.inf_a) * scale};
        const Corner fr{inf_b[w.unit_edge], w.b + dvec3(q.inf_b) * scale};
        const Corner bl{out.vertex(vec4(vec3(w.ray_back_left), 0.0f)), w.a + w.ray_back_left * scale};
        const Corner br{out.vertex(vec4(vec3(w.ray_back_right), 0.0f)), w.b + w.ray_back_right * scale};
        out.polygon({a, b, br, bl}, -w.back.n, withFace(role, kBack));
        out.polygon({a, fl, bl}, -w.left.n, withFace(role, kLeft));
        out.polygon({b, fr, br}, -w.right.n, withFace(role, kRight));
        out.polygon({fl, bl, br, fr},
                    w.ray_back_left + w.ray_back_right + w.ray_front_left + w.ray_front_right,
                    withFace(role, kFar));
      } else {
        auto corner = [&](const dvec3& p) { return Corner{out.vertex(vec4(vec3(p), 1.0f)), p}; };
        const Corner fl = corner(w.far_front_left), fr = corner(w.far_front_right);
        const Corner bl = corner(w.far_back_left), br = corner(w.far_back_right);
        out.polygon({a, b, fr, fl}, -w.front.n, withFace(role, kFront));
        out.polygon({a, b, br, bl}, -w.back.n, withFace(role, kBack));
        out.polygon({a, fl, bl}, -w.left.n, withFace(role, kLeft));
        out.polygon({b, fr, br}, -w.right.n, withFace(role, kRight));
        out.polygon({fl, bl, br, fr}, -w.bottom.n, withFace(role, kFar));
      }
    }
  }
  return f;
}

}  // namespace penumbra
