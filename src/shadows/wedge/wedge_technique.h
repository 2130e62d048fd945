#pragma once
// Soft shadows with penumbra wedges: the 2002 algorithm (`wedge-2002`) and the 2004
// restructured algorithm in its three-pass (`wedge-3pass`) and single-pass (`wedge-1pass`)
// implementations, with tile z-min/z-max culling and z-fail (wedge_technique.cpp).
#include <cstdint>
#include <vector>

#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/technique.h"
#include "shadows/wedge/li_buffer.h"
#include "shadows/wedge/wedge_culling.h"
#include "shadows/wedge_options.h"

namespace penumbra {

TechniqueInfo wedgeTechnique(WedgeAlgorithm algorithm);

// The wedge passes up to the LI buffer (li_buffer.h), for comparing implementations.
// `edge_on_facing` +1 or -1 draws only the edge-on casters with that facing that the casters'
// own silhouettes leave out (LightWedgesOptions, edge_on_sheet.h); when there are none, the
// returned buffer is empty (0 x 0) and no pass ran. `other_facing_meshes`: not null, only those
// meshes cast, with the facing they otherwise leave out (LightWedgesOptions).
WedgeLi renderWedgeLi(WedgeAlgorithm algorithm, const WedgeOptions& options, const Scene& scene,
                      const Light& light, const View& view, const EyeBuffers& eye,
                      const RenderContext& context = {}, int8_t edge_on_facing = 0,
                      const std::vector<uint8_t>* other_facing_meshes = nullptr,
                      const CasterCulling* caster_culling = nullptr);

}  // namespace penumbra
