// The one place a new technique is listed: its folder provides a TechniqueInfo, this table
// names it. Order is the order of `penumbra techniques` and of the conformance suite.
#include "shadows/technique_table.h"

#include "shadows/aliasfree/alias_free_technique.h"
#include "shadows/coverage/coverage_technique.h"
#include "shadows/exact/exact_technique.h"
#include "shadows/heckbert_herf/heckbert_herf_technique.h"
#include "shadows/hierarchical/hierarchical_technique.h"
#include "shadows/mask/mask_technique.h"
#include "shadows/pcss/pcss_technique.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/shadowmap/shadow_map_technique.h"
#include "shadows/volume/volume_technique.h"
#include "shadows/wedge/wedge_technique.h"

namespace penumbra {

std::vector<TechniqueInfo> builtinTechniques() {
  return {
      volumeTechnique(),
      depthBoundsVolumeTechnique(),
      hierarchicalVolumeTechnique(),
      wedgeTechnique(WedgeAlgorithm::ThreePass),
      wedgeTechnique(WedgeAlgorithm::SinglePass),
      wedgeTechnique(WedgeAlgorithm::Original2002),
      coverageTechnique(),
      exactTechnique(),
      heckbertHerfTechnique(),
      maskTechnique(MaskChannel::Alpha),
      maskTechnique(MaskChannel::Colour),
      shadowMapTechnique(),
      pcssTechnique(),
      aliasFreeTechnique(),
      referenceTechnique(),
  };
}

}  // namespace penumbra
