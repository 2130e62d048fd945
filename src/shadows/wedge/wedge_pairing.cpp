#include "shadows/wedge/wedge_pairing.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace penumbra::wedge_detail {
namespace {

// Below this sine an edge's line passes (numerically) through the light centre, whatever the
// option says: its quad normal would be noise.
constexpr double kMinSin = 1e-12;

// Sine of the angle between the unit line direction t and the direction from c to v (0 when v
// is the light centre).
double sinToLight(const dvec3& t, const dvec3& v, const dvec3& c) {
  const dvec3 l = v - c;
  const double len = glm::length(l);
  if (!(len > 0.0)) return 0.0;
  return glm::length(glm::cross(t, l / len));
}

}  // namespace

std::vector<UnitEdge> makeUnitEdges(const Mesh& mesh, const Silhouette& silhouette, const dvec3& c,
                                    double parallel_sin) {
  std::vector<UnitEdge> out;
  const size_t n_positions = mesh.positions.size();
  for (size_t i = 0; i < silhouette.edges.size(); ++i) {
    const SilhouetteEdge& e = silhouette.edges[i];
    PENUMBRA_CHECK(e.v0 < n_positions && e.v1 < n_positions,
                   "mesh '{}': silhouette edge {}-{} out of range ({} positions)", mesh.name, e.v0,
                   e.v1, n_positions);
    PENUMBRA_CHECK(isFinite(mesh.positions[e.v0]) && isFinite(mesh.positions[e.v1]),
                   "mesh '{}': silhouette vertex position is not finite", mesh.name);
    UnitEdge u;
    u.silhouette_edge = uint32_t(i);
    u.va = e.multiplicity > 0 ? e.v0 : e.v1;
    u.vb = e.multiplicity > 0 ? e.v1 : e.v0;
    u.a = dvec3(mesh.positions[u.va]);
    u.b = dvec3(mesh.positions[u.vb]);
    const dvec3 ab = u.b - u.a;
    const double len = glm::length(ab);
    if (len > 0.0) u.t = ab / len;
    const double s = std::min(sinToLight(u.t, u.a, c), sinToLight(u.t, u.b, c));
    u.parallel = !(len > 0.0) || !(s > kMinSin) || !(s > parallel_sin);
    if (!u.parallel) {
      // Normal of the plane (a, b, c) oriented like the quad (b, a, a', b') (counter-clockwise
      // from the front, mesh.h): cross(a - b, a' - a) ~ cross(b - a, c - a). The cross uses
      // the edge midpoint so neither end is favoured.
      const dvec3 q = glm::cross(ab, c - 0.5 * (u.a + u.b));
      const double ql = glm::length(q);
      if (ql > 0.0 && std::isfinite(ql)) {
        u.n = q / ql;
      } else {
        u.parallel = true;
      }
    }
    const uint32_t copies = uint32_t(std::abs(e.multiplicity));
    for (uint32_t k = 0; k < copies; ++k) out.push_back(u);
  }
  return out;
}

Pairings pairAtVertices(const std::vector<UnitEdge>& edges, const dvec3& c) {
  Pairings p;
  p.at_a.assign(edges.size(), kNoWedgeLink);
  p.at_b.assign(edges.size(), kNoWedgeLink);
  // (vertex, kind, unit edge): kind 0 = the edge arrives (its b), 1 = it leaves (its a).
  struct End {
    uint32_t vertex, kind, edge;
  };
  std::vector<End> ends;
  ends.reserve(2 * edges.size());
  for (uint32_t i = 0; i < edges.size(); ++i) {
    ends.push_back({edges[i].vb, 0, i});
    ends.push_back({edges[i].va, 1, i});
  }
  std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) {
    if (x.vertex != y.vertex) return x.vertex < y.vertex;
    if (x.kind != y.kind) return x.kind < y.kind;
    return x.edge < y.edge;
  });
  std::vector<uint32_t> ins, outs, distinct;
  std::vector<bool> taken;
  for (size_t g = 0; g < ends.size();) {
    const uint32_t v = ends[g].vertex;
    ins.clear();
    outs.clear();
    distinct.clear();
    size_t h = g;
    for (; h < ends.size() && ends[h].vertex == v; ++h) {
      (ends[h].kind == 0 ? ins : outs).push_back(ends[h].edge);
      distinct.push_back(edges[ends[h].edge].silhouette_edge);
    }
    g = h;
    std::sort(distinct.begin(), distinct.end());
    const size_t n_distinct =
        size_t(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
    if (n_distinct > 2) ++p.junction_vertices;
    const auto link = [&](uint32_t in, uint32_t out) {
      p.at_b[in] = uint32_t(p.pairings.size());
      p.at_a[out] = uint32_t(p.pairings.size());
      p.pairings.push_back({in, out, v});
    };
    if (ins.size() == 1 && outs.size() == 1) {
      link(ins[0], outs[0]);
    } else {
      // Turning angles measured in the plane perpendicular to the light direction at v, signed
      // about it: the shadow lies on the -n = cross(t, L) side of every edge (n ~ cross(L, t)
      // for the quad normal, see makeUnitEdges), so a turn toward the shadow is negative.
      dvec3 l = (ins.empty() ? edges[outs[0]].a : edges[ins[0]].b) - c;
      const double ll = glm::length(l);
      l = ll > 0.0 ? l / ll : dvec3(0.0);
      const auto project = [&](const dvec3& d) { return d - glm::dot(d, l) * l; };
      taken.assign(outs.size(), false);
      for (const uint32_t in : ins) {
        const dvec3 d_in = project(edges[in].b - edges[in].a);
        size_t best = outs.size();
        double best_angle = 0.0;
        for (size_t j = 0; j < outs.size(); ++j) {
          if (taken[j]) continue;
          const dvec3 d_out = project(edges[outs[j]].b - edges[outs[j]].a);
          // atan2(0, 0) is 0: a degenerate projection (an edge along the light direction)
          // counts as going straight on.
          const double angle =
              std::atan2(glm::dot(glm::cross(d_in, d_out), l), glm::dot(d_in, d_out));
          if (best == outs.size() || angle < best_angle) {
            best = j;
            best_angle = angle;
          }
        }
        if (best == outs.size()) break;
        taken[best] = true;
        link(in, outs[best]);
      }
    }
  }
  return p;
}

}  // namespace penumbra::wedge_detail
