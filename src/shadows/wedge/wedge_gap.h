#pragma once
// Internal to the wedge builder: the extra wedge that fills the notch at a split silhouette
// vertex (2002 paper, section 4.1, Figure 7: "extra wedges around such vertices").
#include <cstdint>

#include "core/math.h"
#include "shadows/wedge/wedge.h"

namespace penumbra::wedge_detail {

// At a split vertex v (wedge.cpp) `in` ends on its own plane at its b == v and `out` starts on
// its own plane at its a == v; a connector umbra quad fans between their front rays. When the
// two end planes leave a notch between the wedges (a corner convex toward the lit side), that
// notch lies inside the umbra volume but in no wedge, so it stays black. This builds the wedge
// that covers it, a cone with its apex at v (a == b == v):
//   front: the connector's plane (v and both front rays), so it is exactly the connector fan;
//   back:  the plane through v and both back rays;
//   left / right: in's end plane and out's end plane, negated, bit for bit, with their rays
//   and equation (2) directions, so the intensity is continuous with both neighbours: on a
//   shared plane both wedges meet their front (back) planes along the same ray.
// Equation (3) then interpolates between the two side planes by distance (edge_dir is chosen
// with equal |side.n . edge_dir|). `connector` is the connector's index in WedgeSet::umbra and
// becomes unit_edge; in_wedge / out_wedge (indices of `in`, `out`) become left_wedge /
// right_wedge. Returns false, leaving `gap` unchanged, where the wedges overlap instead (a
// corner concave toward the lit side: each front ray lies inside the other wedge's end plane),
// or where the cone would be too thin or degenerate to orient its planes.
bool gapWedge(const Wedge& in, uint32_t in_wedge, const Wedge& out, uint32_t out_wedge,
              uint32_t connector, const dvec3& light_center, Wedge& gap);

}  // namespace penumbra::wedge_detail
