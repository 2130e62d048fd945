#pragma once
// Options of Roettger, Irion and Ertl's shadow masks without a stencil (`mask-alpha`,
// `mask-colour`): the hard shadow volumes' count kept in an 8-bit alpha or colour buffer by
// saturating double and halve blends ("Shadow Volumes Revisited", 2002, section 4). For typed
// access:  config.options<penumbra::MaskOptions>().scale = 2;
#include <string>

#include <penumbra/shadows/volume_options.h>

namespace penumbra {

// How the three-valued mask becomes a bilevel one.
enum class MaskNormalisation {
  ThreePass,  // section 4.3, Figure 4: start at 1/4, fronts double, backs halve; *2, invert, *2
  MaxBlend,   // section 4.4, Figure 5: start at 1, fronts halve, backs double; max with 1/2
};
std::string maskNormalisationName(MaskNormalisation n);  // "three-pass", "max-blend"

// What the paper does with a shadowed pixel (Table 1's columns).
enum class MaskShadowMode {
  Black,       // set to black
  Ambient,     // black, then the scene drawn again with its ambient term added
  Attenuated,  // the pixel's colour times 1/2
};
std::string maskShadowModeName(MaskShadowMode m);  // "black", "ambient", "attenuated"

struct MaskOptions {
  VolumeMode mode = VolumeMode::Auto;  // as the `volume` technique, per caster
  MaskNormalisation normalisation = MaskNormalisation::ThreePass;
  MaskShadowMode shadow = MaskShadowMode::Black;  // max-blend gives attenuated shadows only
  // The mask is computed at 1/scale of the screen resolution (section 4.5) with its own depth
  // pass, then bilinearly magnified: 1, 2 or 4.
  int scale = 1;
};

}  // namespace penumbra
