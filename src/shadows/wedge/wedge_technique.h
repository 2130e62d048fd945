#pragma once
#include "shadows/technique.h"

namespace penumbra {

// Soft shadows with penumbra wedges: the 2002 algorithm (TechniqueKind::Wedge2002) and the
// 2004 restructured algorithm in its three-pass and single-pass implementations, with tile
// z-min/z-max culling and z-fail (wedge_technique.cpp).
TechniqueResult renderWedges(const TechniqueOptions& options, const Scene& scene,
                             const Light& light, const View& view, const EyeBuffers& eye);

}  // namespace penumbra
