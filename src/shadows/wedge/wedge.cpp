#include "shadows/wedge/wedge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "shadows/wedge/wedge_gap.h"
#include "shadows/wedge/wedge_pairing.h"
#include "shadows/wedge/wedge_sides.h"

// How the wedges are put together (2002 paper, section 4.1):
//
// - Edges keep their vertices. The 2003/2004 follow-ups move the farther vertex of an edge
//   toward the light; we do not: the front-plane quads are then exactly the quads of the
//   original silhouette, watertight with their neighbours, and with r = 0 they are the hard
//   shadow volume bit for bit (shadows/stages/caster_volumes/caster_volume.h).
// - Each pairing of an incoming and an outgoing unit edge at a vertex (wedge_pairing.h) makes one
//   side plane, the right plane of the incoming wedge and (negated) the left plane of the
//   outgoing one, and one front-line direction that both wedges' ray_front_* and both umbra
//   quads use. The equation (2) direction is shared too, so the intensity is continuous across
//   the plane: along a direction in the plane both wedges meet their front (back) planes on the
//   same line, where the two front (back) planes and the side plane meet.
// - Nearly parallel edges (section 8: "we remove such edges and shorten & connect its
//   neighbors"). Such an edge gets no wedge. The non-parallel edges before and after a run of
//   them (e0 ending at v, e2 starting at w) share one side plane through v and w holding the sum
//   of their quad normals: seen from the light it bisects the corner e0 and e2 make, so the two
//   wedges still cover the penumbra with no gap or overlap, and both polyhedra keep their
//   vertices. The intensity is exactly continuous across it only when v == w; otherwise e0 and
//   e2 meet that plane along slightly different front (back) lines, a step of order
//   |w - v| r / distance, near the occluder (the artifact section 8 warns of). The umbra quads
//   follow the wedges: e0's quad ends along e0's front ray in that plane, e2's starts along
//   e2's, and the parallel edges' quads use those two directions at v and at w (the hard
//   direction vec3(p) - c at vertices inside the run). So every front face coincides with its
//   umbra quad, the parallel quads lie in the shared side plane, and the invariant "every
//   pairing's umbra direction is shared by the two quads it joins" holds. (Using the hard
//   direction at v and w instead would also close the volume, but it bends e0's umbra quad away
//   from e0's front face, leaving a sliver of penumbra outside the umbra volume that the LI
//   clamp turns fully lit.)
// - At acute silhouette corners (section 4.1, Figure 7) the shared front (back) line runs far
//   out along the corner's bisector (1 / sin(corner / 2) times the light's angular radius from
//   the light direction), and if the corner is also steep to the light it can fall along or
//   behind an edge, where no wedge can end on it. The umbra quads would follow it into a spike
//   that the wedges, cut where their side planes cross (Figure 6), do not cover: a long dark
//   streak in the 2004 algorithm. So a pairing whose lines leave twice the light's cone, or
//   fall behind an edge, is split (wedge_sides.h, sideFits): each wedge ends on its own plane
//   through the vertex and the light's diameter along its n (as an unpaired end), so the two
//   may overlap or leave a notch at the tip. Each umbra quad follows its own wedge's front
//   ray, and a connector quad (a == b == the vertex) fans between the two directions at
//   infinity, so the volume stays closed and every front face is still exactly its umbra quad.
//   The notch lies inside that closed umbra volume, so with no wedge over it it renders as a
//   short dark dash at the tip (bunny-lowres's ears); one extra wedge per notch, as Figure 7
//   suggests, covers it (wedge_gap.h: a cone from the vertex between the two end planes whose
//   front face is the connector). Counted in split_vertices. (If the shared plane
//   of a run of parallel edges does not fit, the same happens without connectors: the
//   parallel quads already span the two directions.)
// - An end with no partner (a silhouette that is not a closed loop, or a loop whose only
//   non-parallel edge is this one) is closed by its own plane through the vertex and the light
//   centre (wedge_sides.h, loneSide); counted in unpaired_ends.
// - Figure 6 (the side planes cross inside the wedge): wedge_sides.h, cutWhereSidesCross.
// - Figure 7 (extra wedges at acute vertices): only the one gap wedge at split vertices above;
//   the paper's fans of several wedges around every acute vertex are not built, and no option
//   builds them (README, "Differences from the papers").
namespace penumbra {

using wedge_detail::EdgePlanes;
using wedge_detail::SidePlane;
using wedge_detail::UnitEdge;

namespace {

Plane negated(const Plane& p) { return Plane{-p.n, -p.d}; }

// Where a wedge end meets its side plane, as seen from that wedge.
struct WedgeEnd {
  Plane plane;  // inward for this wedge
  dvec3 ray_front{0.0}, ray_back{0.0}, dir{0.0};
  uint32_t neighbour = kNoWedgeLink;  // unit edge whose wedge shares the plane
};

}  // namespace

WedgeSet buildWedges(const Mesh& mesh, const Silhouette& silhouette, const Light& light,
                     const WedgeBuildOptions& options) {
  PENUMBRA_CHECK(isFinite(light.center) && std::isfinite(light.radius) && light.radius >= 0.0f,
                 "penumbra wedges: the light needs a finite centre and a finite radius >= 0 "
                 "(radius {})",
                 light.radius);
  PENUMBRA_CHECK(options.parallel_degrees >= 0.0 && options.parallel_degrees < 90.0,
                 "penumbra wedges: parallel_degrees must be in [0, 90), not {}",
                 options.parallel_degrees);
  const dvec3 c(light.center);
  const double r = double(light.radius);
  const double parallel_sin = std::sin(options.parallel_degrees * std::numbers::pi / 180.0);

  const std::vector<UnitEdge> edges =
      wedge_detail::makeUnitEdges(mesh, silhouette, c, parallel_sin);
  const wedge_detail::Pairings pairs = wedge_detail::pairAtVertices(edges, c);
  const size_t n = edges.size();
  WedgeSet out;
  out.junction_vertices = pairs.junction_vertices;

  // The hard shadow volume's direction at a vertex, in float exactly as the caster volumes stage
  // computes it, and its double unit vector for the r == 0 rays.
  const auto hard = [&](uint32_t v) { return mesh.positions[v] - light.center; };
  const auto hardUnit = [&](uint32_t v) {
    const dvec3 d(hard(v));
    const double len = glm::length(d);
    return len > 0.0 ? d / len : dvec3(0.0, -1.0, 0.0);
  };
  // The umbra quads take the wedges' front rays, except with r == 0, where the hard direction
  // makes the umbra the hard volume bit for bit.
  const auto umbraDirection = [&](const dvec3& ray_front, uint32_t v) {
    return r > 0.0 ? vec3(ray_front) : hard(v);
  };

  std::vector<EdgePlanes> planes(n);
  for (size_t e = 0; e < n; ++e)
    if (!edges[e].parallel) planes[e] = wedge_detail::edgePlanes(edges[e], c, r);

  // Umbra directions at each pairing's vertex: dir_in for the incoming quad's b end, dir_out
  // for the outgoing quad's a end. They are one value (so bit-identical) except at a split
  // pairing, where a connector quad joins them. Hard by default: what parallel edges inside a
  // run keep. One more per unpaired end.
  const size_t n_pairings = pairs.pairings.size();
  std::vector<vec3> dir_in(n_pairings), dir_out(n_pairings);
  std::vector<uint8_t> split(n_pairings, 0);
  for (size_t p = 0; p < n_pairings; ++p) dir_in[p] = dir_out[p] = hard(pairs.pairings[p].vertex);
  const auto setPairingDirection = [&](uint32_t p, const vec3& d) { dir_in[p] = dir_out[p] = d; };
  std::vector<vec3> lone_a(n), lone_b(n);
  for (size_t e = 0; e < n; ++e) {
    lone_a[e] = hard(edges[e].va);
    lone_b[e] = hard(edges[e].vb);
  }

  std::vector<WedgeEnd> left(n), right(n);
  const auto closeAlone = [&](uint32_t e, bool at_b, uint32_t pairing) {
    const uint32_t v = at_b ? edges[e].vb : edges[e].va;
    const SidePlane s = wedge_detail::loneSide(edges[e], at_b, c, r, hardUnit(v));
    (at_b ? right : left)[e] = WedgeEnd{s.plane, s.front_in, s.back_in, s.dir, kNoWedgeLink};
    const vec3 u = umbraDirection(s.front_in, v);
    if (pairing != kNoWedgeLink) {
      setPairingDirection(pairing, u);
    } else {
      (at_b ? lone_b : lone_a)[e] = u;
    }
    ++out.unpaired_ends;
  };
  // Shares the side plane between e0 (ending there) and e2 (starting there) if it gives both a
  // usable end; otherwise each wedge gets its own end plane, as if alone (the caller then joins
  // their umbra quads). Returns whether the plane was shared.
  const auto join = [&](uint32_t e0, uint32_t e2, const SidePlane& s) {
    const Plane flipped = negated(s.plane);
    if (wedge_detail::sideFits(edges[e0], planes[e0], s.plane, s.front_in, s.back_in, true, c, r) &&
        wedge_detail::sideFits(edges[e2], planes[e2], flipped, s.front_out, s.back_out, false, c,
                               r)) {
      right[e0] = WedgeEnd{s.plane, s.front_in, s.back_in, s.dir, e2};
      left[e2] = WedgeEnd{flipped, s.front_out, s.back_out, s.dir, e0};
      return true;
    }
    for (const bool at_b : {true, false}) {
      const uint32_t e = at_b ? e0 : e2;
      const uint32_t v = at_b ? edges[e].vb : edges[e].va;
      const SidePlane alone = wedge_detail::loneSide(edges[e], at_b, c, r, hardUnit(v));
      (at_b ? right : left)[e] =
          WedgeEnd{alone.plane, alone.front_in, alone.back_in, alone.dir, kNoWedgeLink};
    }
    ++out.split_vertices;
    return false;
  };
  // Walks a run of parallel edges from pairing p in the given direction; returns the first
  // non-parallel unit edge reached (kNoWedgeLink if the chain breaks first) and the last
  // pairing crossed.
  const auto walk = [&](uint32_t p, bool forward, uint32_t& last) {
    last = p;
    uint32_t q = forward ? pairs.pairings[p].out : pairs.pairings[p].in;
    for (size_t steps = 0; edges[q].parallel && steps < n; ++steps) {
      const uint32_t next = forward ? pairs.at_b[q] : pairs.at_a[q];
      if (next == kNoWedgeLink) return kNoWedgeLink;
      last = next;
      q = forward ? pairs.pairings[next].out : pairs.pairings[next].in;
    }
    return edges[q].parallel ? kNoWedgeLink : q;
  };

  for (uint32_t e = 0; e < n; ++e) {
    if (edges[e].parallel) continue;
    // The b end: this edge is the pairing's incoming edge, so it builds the shared plane.
    const uint32_t pb = pairs.at_b[e];
    if (pb == kNoWedgeLink) {
      closeAlone(e, true, kNoWedgeLink);
    } else if (const uint32_t next = pairs.pairings[pb].out; !edges[next].parallel) {
      const uint32_t v = pairs.pairings[pb].vertex;
      const SidePlane s = wedge_detail::regularSide(edges[e], planes[e], edges[next], planes[next],
                                                    c, r, hardUnit(v));
      if (join(e, next, s)) {
        setPairingDirection(pb, umbraDirection(s.front_in, v));
      } else {
        // Split: each quad follows its own wedge's front ray; a connector fans between them.
        dir_in[pb] = umbraDirection(right[e].ray_front, v);
        dir_out[pb] = umbraDirection(left[next].ray_front, v);
        split[pb] = 1;
      }
    } else {
      uint32_t last = pb;
      const uint32_t e2 = walk(pb, true, last);
      if (e2 != kNoWedgeLink && e2 != e) {
        const SidePlane s =
            wedge_detail::bridgedSide(edges[e], planes[e], edges[e2], planes[e2], c, r,
                                      hardUnit(edges[e].vb), hardUnit(edges[e2].va));
        // Shared or not, the run's quads take e0's and e2's front rays at v and w (they need no
        // connector: the parallel quads span the difference).
        join(e, e2, s);
        setPairingDirection(pb, umbraDirection(right[e].ray_front, edges[e].vb));
        setPairingDirection(last, umbraDirection(left[e2].ray_front, edges[e2].va));
      } else {
        closeAlone(e, true, pb);
      }
    }
    // The a end: built by the incoming edge's b end above, unless there is none.
    const uint32_t pa = pairs.at_a[e];
    if (pa == kNoWedgeLink) {
      closeAlone(e, false, kNoWedgeLink);
    } else if (edges[pairs.pairings[pa].in].parallel) {
      uint32_t last = pa;
      const uint32_t e0 = walk(pa, false, last);
      if (e0 == kNoWedgeLink || e0 == e) closeAlone(e, false, pa);
    }
  }

  std::vector<uint32_t> wedge_of(n, kNoWedgeLink);
  out.wedges.reserve(n);
  for (uint32_t e = 0; e < n; ++e) {
    const UnitEdge& u = edges[e];
    if (u.parallel) {
      ++out.parallel_edges_removed;
      continue;
    }
    Wedge w;
    w.va = u.va;
    w.vb = u.vb;
    w.a = u.a;
    w.b = u.b;
    w.front = planes[e].front;
    w.back = planes[e].back;
    w.left = left[e].plane;
    w.right = right[e].plane;
    w.dir_left = left[e].dir;
    w.dir_right = right[e].dir;
    w.edge_dir = u.t;
    w.normal = u.n;
    w.ray_front_left = left[e].ray_front;
    w.ray_back_left = left[e].ray_back;
    w.ray_front_right = right[e].ray_front;
    w.ray_back_right = right[e].ray_back;
    w.unit_edge = e;
    w.flat = !(r > 0.0);
    if (!w.flat) {
      if (!wedge_detail::cutWhereSidesCross(w, c)) {
        w.flat = true;
        ++out.degenerate_wedges;
      } else if (w.finite) {
        ++out.finite_wedges;
      }
    }
    wedge_of[e] = uint32_t(out.wedges.size());
    out.wedges.push_back(w);
  }
  for (Wedge& w : out.wedges) {
    const uint32_t e = w.unit_edge;
    if (left[e].neighbour != kNoWedgeLink) w.left_wedge = wedge_of[left[e].neighbour];
    if (right[e].neighbour != kNoWedgeLink) w.right_wedge = wedge_of[right[e].neighbour];
  }

  // Quads of the unit edges (index = unit edge), then one connector per split pairing.
  std::vector<uint32_t> connector_of(n_pairings, kNoWedgeLink);
  uint32_t n_quads = uint32_t(n);
  for (size_t p = 0; p < n_pairings; ++p)
    if (split[p]) connector_of[p] = n_quads++;
  out.umbra.resize(n_quads);
  for (uint32_t e = 0; e < n; ++e) {
    UmbraQuad& q = out.umbra[e];
    q.va = edges[e].va;
    q.vb = edges[e].vb;
    const uint32_t pa = pairs.at_a[e], pb = pairs.at_b[e];
    q.inf_a = pa != kNoWedgeLink ? dir_out[pa] : lone_a[e];
    q.inf_b = pb != kNoWedgeLink ? dir_in[pb] : lone_b[e];
    if (pa != kNoWedgeLink)
      q.prev = connector_of[pa] != kNoWedgeLink ? connector_of[pa] : pairs.pairings[pa].in;
    if (pb != kNoWedgeLink)
      q.next = connector_of[pb] != kNoWedgeLink ? connector_of[pb] : pairs.pairings[pb].out;
    q.has_wedge = !edges[e].parallel;
  }
  for (size_t p = 0; p < n_pairings; ++p) {
    if (connector_of[p] == kNoWedgeLink) continue;
    // The fan at infinity from the incoming quad's direction to the outgoing one's: a quad
    // (b, a, a', b') with a == b, so it closes the volume in the same orientation.
    UmbraQuad& q = out.umbra[connector_of[p]];
    q.va = q.vb = pairs.pairings[p].vertex;
    q.inf_a = dir_in[p];
    q.inf_b = dir_out[p];
    q.prev = pairs.pairings[p].in;
    q.next = pairs.pairings[p].out;
    q.has_wedge = false;
    // The notch between the two wedges' end planes (if they do not overlap there).
    const uint32_t in = pairs.pairings[p].in, next = pairs.pairings[p].out;
    Wedge gap;
    if (r > 0.0 && wedge_detail::gapWedge(out.wedges[wedge_of[in]], wedge_of[in],
                                          out.wedges[wedge_of[next]], wedge_of[next],
                                          connector_of[p], c, gap))
      out.gap_wedges.push_back(gap);
  }
  return out;
}

WedgeIntensityConstants wedgeIntensityConstants(const Wedge& w) {
  WedgeIntensityConstants k;
  k.front_left = std::fabs(glm::dot(w.front.n, w.dir_left));
  k.back_left = std::fabs(glm::dot(w.back.n, w.dir_left));
  k.front_right = std::fabs(glm::dot(w.front.n, w.dir_right));
  k.back_right = std::fabs(glm::dot(w.back.n, w.dir_right));
  k.left = std::fabs(glm::dot(w.left.n, w.edge_dir));
  k.right = std::fabs(glm::dot(w.right.n, w.edge_dir));
  return k;
}

double intensityFromPlaneValues(const WedgeIntensityConstants& k, double f, double b, double l,
                                double r) {
  // Points just outside count as on the plane (also turns a NaN into 0).
  f = f > 0.0 ? f : 0.0;
  b = b > 0.0 ? b : 0.0;
  l = l > 0.0 ? l : 0.0;
  r = r > 0.0 ? r : 0.0;
  // Equation (2): s_l = t_lb / (t_lf + t_lb) with t_lf = f / front_left, t_lb = b / back_left,
  // times front_left * back_left: s_l = b front_left / dl. Likewise s_r.
  const double dl = f * k.back_left + b * k.front_left;
  const double dr = f * k.back_right + b * k.front_right;
  // Equation (3): s = (t_r s_l + t_l s_r) / (t_r + t_l), t_l = l / left, t_r = r / right,
  // times left * right: weights r left (for s_l) and l right (for s_r).
  const double wl = r * k.left, wr = l * k.right;
  // Least common denominator: one division (section 4.2).
  const double den = (wl + wr) * dl * dr;
  double s;
  if (den >= std::numeric_limits<double>::min() && den <= std::numeric_limits<double>::max()) {
    s = b * (wl * k.front_left * dr + wr * k.front_right * dl) / den;
  } else {
    // A 0/0 (on the edge line, where both side planes meet, or a side direction parallel to
    // the front and back planes) or a denormal/overflowing product: the ratios one by one.
    const double sl = dl > 0.0 ? b * k.front_left / dl : 0.5;
    const double sr = dr > 0.0 ? b * k.front_right / dr : 0.5;
    s = wl + wr > 0.0 ? (wl * sl + wr * sr) / (wl + wr) : 0.5 * (sl + sr);
  }
  if (!(s > 0.0)) return 0.0;
  return s < 1.0 ? s : 1.0;
}

double applyFalloff(double s, Falloff falloff) {
  if (falloff == Falloff::Smooth) return s * s * (3.0 - 2.0 * s);
  return s;
}

double wedgeIntensity(const Wedge& wedge, const dvec3& p, Falloff falloff) {
  const double s =
      intensityFromPlaneValues(wedgeIntensityConstants(wedge), wedge.front.eval(p),
                               wedge.back.eval(p), wedge.left.eval(p), wedge.right.eval(p));
  return applyFalloff(s, falloff);
}

bool insideWedge(const Wedge& wedge, const dvec3& p) {
  if (wedge.flat) return false;
  // The four planes only, as the penumbra passes rasterize the wedge (light_wedges.cpp): no
  // Figure 6 bottom cut, whose far side no wedge would cover.
  return wedge.front.eval(p) >= 0.0 && wedge.back.eval(p) >= 0.0 && wedge.left.eval(p) >= 0.0 &&
         wedge.right.eval(p) >= 0.0;
}

}  // namespace penumbra
