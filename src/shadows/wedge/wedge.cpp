#include "shadows/wedge/wedge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

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

// The wedges and umbra quads of one silhouette (2002 paper, section 4.1, as the comment above
// describes): the side planes at each vertex pairing, then the wedges, then the quads. One
// object per buildWedges call; its steps share the per-edge and per-pairing arrays below.
class WedgeSetBuilder {
 public:
  WedgeSetBuilder(const Mesh& mesh, const Silhouette& silhouette, const Light& light,
                  const WedgeBuildOptions& options)
      : mesh_(mesh), light_(light), c_(light.center), r_(double(light.radius)),
        edges_(wedge_detail::makeUnitEdges(
            mesh, silhouette, c_,
            std::sin(options.parallel_degrees * std::numbers::pi / 180.0))),
        pairs_(wedge_detail::pairAtVertices(edges_, c_)), n_(edges_.size()),
        n_pairings_(pairs_.pairings.size()), planes_(n_), dir_in_(n_pairings_),
        dir_out_(n_pairings_), split_(n_pairings_, 0), lone_a_(n_), lone_b_(n_), left_(n_),
        right_(n_), wedge_of_(n_, kNoWedgeLink) {
    out_.junction_vertices = pairs_.junction_vertices;
    for (size_t e = 0; e < n_; ++e)
      if (!edges_[e].parallel) planes_[e] = wedge_detail::edgePlanes(edges_[e], c_, r_);
    // Umbra directions at each pairing's vertex: dir_in for the incoming quad's b end, dir_out
    // for the outgoing quad's a end. They are one value (so bit-identical) except at a split
    // pairing, where a connector quad joins them. Hard by default: what parallel edges inside
    // a run keep. One more per unpaired end.
    for (size_t p = 0; p < n_pairings_; ++p)
      dir_in_[p] = dir_out_[p] = hard(pairs_.pairings[p].vertex);
    for (size_t e = 0; e < n_; ++e) {
      lone_a_[e] = hard(edges_[e].va);
      lone_b_[e] = hard(edges_[e].vb);
    }
  }

  WedgeSet build() {
    for (uint32_t e = 0; e < n_; ++e) {
      if (edges_[e].parallel) continue;
      closeEndB(e);
      closeEndA(e);
    }
    assembleWedges();
    buildUmbraQuads();
    return std::move(out_);
  }

 private:
  // The hard shadow volume's direction at a vertex, in float exactly as the caster volumes stage
  // computes it, and its double unit vector for the r == 0 rays.
  vec3 hard(uint32_t v) const { return mesh_.positions[v] - light_.center; }
  dvec3 hardUnit(uint32_t v) const {
    const dvec3 d(hard(v));
    const double len = glm::length(d);
    return len > 0.0 ? d / len : dvec3(0.0, -1.0, 0.0);
  }
  // The umbra quads take the wedges' front rays, except with r == 0, where the hard direction
  // makes the umbra the hard volume bit for bit.
  vec3 umbraDirection(const dvec3& ray_front, uint32_t v) const {
    return r_ > 0.0 ? vec3(ray_front) : hard(v);
  }
  void setPairingDirection(uint32_t p, const vec3& d) { dir_in_[p] = dir_out_[p] = d; }

  // An end with no partner closed by its own plane (wedge_sides.h, loneSide).
  void closeAlone(uint32_t e, bool at_b, uint32_t pairing) {
    const uint32_t v = at_b ? edges_[e].vb : edges_[e].va;
    const SidePlane s = wedge_detail::loneSide(edges_[e], at_b, c_, r_, hardUnit(v));
    (at_b ? right_ : left_)[e] = WedgeEnd{s.plane, s.front_in, s.back_in, s.dir, kNoWedgeLink};
    const vec3 u = umbraDirection(s.front_in, v);
    if (pairing != kNoWedgeLink) {
      setPairingDirection(pairing, u);
    } else {
      (at_b ? lone_b_ : lone_a_)[e] = u;
    }
    ++out_.unpaired_ends;
  }

  // Shares the side plane between e0 (ending there) and e2 (starting there) if it gives both a
  // usable end; otherwise each wedge gets its own end plane, as if alone (the caller then joins
  // their umbra quads; section 4.1, Figure 7). Returns whether the plane was shared.
  bool join(uint32_t e0, uint32_t e2, const SidePlane& s) {
    const Plane flipped = negated(s.plane);
    if (wedge_detail::sideFits(edges_[e0], planes_[e0], s.plane, s.front_in, s.back_in, true, c_,
                               r_) &&
        wedge_detail::sideFits(edges_[e2], planes_[e2], flipped, s.front_out, s.back_out, false,
                               c_, r_)) {
      right_[e0] = WedgeEnd{s.plane, s.front_in, s.back_in, s.dir, e2};
      left_[e2] = WedgeEnd{flipped, s.front_out, s.back_out, s.dir, e0};
      return true;
    }
    for (const bool at_b : {true, false}) {
      const uint32_t e = at_b ? e0 : e2;
      const uint32_t v = at_b ? edges_[e].vb : edges_[e].va;
      const SidePlane alone = wedge_detail::loneSide(edges_[e], at_b, c_, r_, hardUnit(v));
      (at_b ? right_ : left_)[e] =
          WedgeEnd{alone.plane, alone.front_in, alone.back_in, alone.dir, kNoWedgeLink};
    }
    ++out_.split_vertices;
    return false;
  }

  // Walks a run of parallel edges from pairing p in the given direction; returns the first
  // non-parallel unit edge reached (kNoWedgeLink if the chain breaks first) and the last
  // pairing crossed.
  uint32_t walk(uint32_t p, bool forward, uint32_t& last) const {
    last = p;
    uint32_t q = forward ? pairs_.pairings[p].out : pairs_.pairings[p].in;
    for (size_t steps = 0; edges_[q].parallel && steps < n_; ++steps) {
      const uint32_t next = forward ? pairs_.at_b[q] : pairs_.at_a[q];
      if (next == kNoWedgeLink) return kNoWedgeLink;
      last = next;
      q = forward ? pairs_.pairings[next].out : pairs_.pairings[next].in;
    }
    return edges_[q].parallel ? kNoWedgeLink : q;
  }

  // The b end of non-parallel edge e: this edge is the pairing's incoming edge, so it builds
  // the shared side plane (section 4.1), across a run of nearly parallel edges (section 8)
  // where one follows.
  void closeEndB(uint32_t e) {
    const uint32_t pb = pairs_.at_b[e];
    if (pb == kNoWedgeLink) {
      closeAlone(e, true, kNoWedgeLink);
    } else if (const uint32_t next = pairs_.pairings[pb].out; !edges_[next].parallel) {
      const uint32_t v = pairs_.pairings[pb].vertex;
      const SidePlane s = wedge_detail::regularSide(edges_[e], planes_[e], edges_[next],
                                                    planes_[next], c_, r_, hardUnit(v));
      if (join(e, next, s)) {
        setPairingDirection(pb, umbraDirection(s.front_in, v));
      } else {
        // Split: each quad follows its own wedge's front ray; a connector fans between them.
        dir_in_[pb] = umbraDirection(right_[e].ray_front, v);
        dir_out_[pb] = umbraDirection(left_[next].ray_front, v);
        split_[pb] = 1;
      }
    } else {
      uint32_t last = pb;
      const uint32_t e2 = walk(pb, true, last);
      if (e2 != kNoWedgeLink && e2 != e) {
        const SidePlane s =
            wedge_detail::bridgedSide(edges_[e], planes_[e], edges_[e2], planes_[e2], c_, r_,
                                      hardUnit(edges_[e].vb), hardUnit(edges_[e2].va));
        // Shared or not, the run's quads take e0's and e2's front rays at v and w (they need
        // no connector: the parallel quads span the difference).
        join(e, e2, s);
        setPairingDirection(pb, umbraDirection(right_[e].ray_front, edges_[e].vb));
        setPairingDirection(last, umbraDirection(left_[e2].ray_front, edges_[e2].va));
      } else {
        closeAlone(e, true, pb);
      }
    }
  }

  // The a end of non-parallel edge e: built by the incoming edge's b end (closeEndB), unless
  // there is none.
  void closeEndA(uint32_t e) {
    const uint32_t pa = pairs_.at_a[e];
    if (pa == kNoWedgeLink) {
      closeAlone(e, false, kNoWedgeLink);
    } else if (edges_[pairs_.pairings[pa].in].parallel) {
      uint32_t last = pa;
      const uint32_t e0 = walk(pa, false, last);
      if (e0 == kNoWedgeLink || e0 == e) closeAlone(e, false, pa);
    }
  }

  // One wedge per non-parallel unit edge, from its front and back planes and its two ends,
  // cut where its side planes cross (Figure 6); then the links to the neighbours sharing an
  // end plane.
  void assembleWedges() {
    out_.wedges.reserve(n_);
    for (uint32_t e = 0; e < n_; ++e) {
      const UnitEdge& u = edges_[e];
      if (u.parallel) {
        ++out_.parallel_edges_removed;
        continue;
      }
      Wedge w;
      w.va = u.va;
      w.vb = u.vb;
      w.a = u.a;
      w.b = u.b;
      w.front = planes_[e].front;
      w.back = planes_[e].back;
      w.left = left_[e].plane;
      w.right = right_[e].plane;
      w.dir_left = left_[e].dir;
      w.dir_right = right_[e].dir;
      w.edge_dir = u.t;
      w.normal = u.n;
      w.ray_front_left = left_[e].ray_front;
      w.ray_back_left = left_[e].ray_back;
      w.ray_front_right = right_[e].ray_front;
      w.ray_back_right = right_[e].ray_back;
      w.unit_edge = e;
      w.flat = !(r_ > 0.0);
      if (!w.flat) {
        if (!wedge_detail::cutWhereSidesCross(w, c_)) {
          w.flat = true;
          ++out_.degenerate_wedges;
        } else if (w.finite) {
          ++out_.finite_wedges;
        }
      }
      wedge_of_[e] = uint32_t(out_.wedges.size());
      out_.wedges.push_back(w);
    }
    for (Wedge& w : out_.wedges) {
      const uint32_t e = w.unit_edge;
      if (left_[e].neighbour != kNoWedgeLink) w.left_wedge = wedge_of_[left_[e].neighbour];
      if (right_[e].neighbour != kNoWedgeLink) w.right_wedge = wedge_of_[right_[e].neighbour];
    }
  }

  // Quads of the unit edges (index = unit edge), then one connector per split pairing, with
  // the gap wedge over its notch (Figure 7).
  void buildUmbraQuads() {
    std::vector<uint32_t> connector_of(n_pairings_, kNoWedgeLink);
    uint32_t n_quads = uint32_t(n_);
    for (size_t p = 0; p < n_pairings_; ++p)
      if (split_[p]) connector_of[p] = n_quads++;
    out_.umbra.resize(n_quads);
    for (uint32_t e = 0; e < n_; ++e) {
      UmbraQuad& q = out_.umbra[e];
      q.va = edges_[e].va;
      q.vb = edges_[e].vb;
      const uint32_t pa = pairs_.at_a[e], pb = pairs_.at_b[e];
      q.inf_a = pa != kNoWedgeLink ? dir_out_[pa] : lone_a_[e];
      q.inf_b = pb != kNoWedgeLink ? dir_in_[pb] : lone_b_[e];
      if (pa != kNoWedgeLink)
        q.prev = connector_of[pa] != kNoWedgeLink ? connector_of[pa] : pairs_.pairings[pa].in;
      if (pb != kNoWedgeLink)
        q.next = connector_of[pb] != kNoWedgeLink ? connector_of[pb] : pairs_.pairings[pb].out;
      q.has_wedge = !edges_[e].parallel;
    }
    for (size_t p = 0; p < n_pairings_; ++p) {
      if (connector_of[p] == kNoWedgeLink) continue;
      // The fan at infinity from the incoming quad's direction to the outgoing one's: a quad
      // (b, a, a', b') with a == b, so it closes the volume in the same orientation.
      UmbraQuad& q = out_.umbra[connector_of[p]];
      q.va = q.vb = pairs_.pairings[p].vertex;
      q.inf_a = dir_in_[p];
      q.inf_b = dir_out_[p];
      q.prev = pairs_.pairings[p].in;
      q.next = pairs_.pairings[p].out;
      q.has_wedge = false;
      // The notch between the two wedges' end planes (if they do not overlap there).
      const uint32_t in = pairs_.pairings[p].in, next = pairs_.pairings[p].out;
      Wedge gap;
      if (r_ > 0.0 && wedge_detail::gapWedge(out_.wedges[wedge_of_[in]], wedge_of_[in],
                                              out_.wedges[wedge_of_[next]], wedge_of_[next],
                                              connector_of[p], c_, gap))
        out_.gap_wedges.push_back(gap);
    }
  }

  const Mesh& mesh_;
  const Light& light_;
  const dvec3 c_;
  const double r_;
  const std::vector<UnitEdge> edges_;
  const wedge_detail::Pairings pairs_;
  const size_t n_, n_pairings_;
  std::vector<EdgePlanes> planes_;
  std::vector<vec3> dir_in_, dir_out_;
  std::vector<uint8_t> split_;
  std::vector<vec3> lone_a_, lone_b_;
  std::vector<WedgeEnd> left_, right_;
  std::vector<uint32_t> wedge_of_;
  WedgeSet out_;
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
  return WedgeSetBuilder(mesh, silhouette, light, options).build();
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
