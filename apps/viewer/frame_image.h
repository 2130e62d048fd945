#pragma once
// What the frame area shows, as 8-bit RGB ready for a texture: the shaded frame, or one of the
// overlays (a light's visibility alone, its penumbra pixels over the shaded frame, the depth,
// the tiles' depth ranges), or the comparison with the oracle (split view or error heat map).
#include <optional>

#include <penumbra/penumbra.h>

#include "oracle_worker.h"
#include "viewer_model.h"

namespace penumbra::viewer {

using Rgb8Image = Image<glm::u8vec3>;

// The shaded frame as the PNG writer encodes it (sRGB, core/image_io.h).
Rgb8Image shadedImage(const FrameResult& frame);
// `light`'s visibility as gray.
Rgb8Image visibilityImage(const FrameResult& frame, size_t light);
// The shaded frame with the pixels in `light`'s penumbra (0 < visibility < 1) tinted magenta.
Rgb8Image penumbraImage(const FrameResult& frame, size_t light);
// The eye pass's depth (reversed-Z: near is bright), stretched over the covered pixels' range;
// the background black.
Rgb8Image depthImage(const FrameResult& frame);
// Each 16x16 tile coloured by its depth range z-max - z-min (the 2004 paper's culling test
// works on it: a tile with a small range is cheap to classify), stretched over the frame's.
Rgb8Image tileRangeImage(const FrameResult& frame);

// `light`'s debug layer `name` (DebugLayer, shadows/technique.h) over the shaded frame, dimmed
// to a third: each pixel with a value coloured by it on the heat map's scale (brightest at the
// frame's largest value), silhouette edges in yellow. The dimmed frame alone when the technique
// published no such layer (frameHasLayer).
Rgb8Image debugLayerImage(const FrameResult& frame, size_t light, const std::string& name);
bool frameHasLayer(const FrameResult& frame, size_t light, const std::string& name);

Rgb8Image overlayImage(const FrameResult& frame, Overlay overlay, size_t light);

// Pixels as the window's texture takes them: 32 bits, 0xFFRRGGBB (SDL's ARGB8888), rows
// `pitch` bytes apart. The shaded frame is encoded straight into them (the frame the window
// shows most, converted once, with no 24-bit image between); anything else is packed from its
// RGB image.
void shadedPixels(const FrameResult& frame, void* pixels, int pitch);
void packPixels(const Rgb8Image& image, void* pixels, int pitch);

// The technique against the oracle over the pixels showing geometry.
struct Comparison {
  ImageDifference difference;
  int oracle_rays = 0;
  int oracle_passes = 0;
};
Comparison compareWithOracle(const FrameResult& frame, const OracleImage& oracle,
                             double tolerance);
// Split view: the technique's visibility left of the middle, the oracle's right of it, a
// one-pixel line between. Heat map: |technique - oracle| (metrics/heatmap.h).
Rgb8Image splitImage(const FrameResult& frame, const OracleImage& oracle);
Rgb8Image heatmapImage(const FrameResult& frame, const OracleImage& oracle, float scale);

}  // namespace penumbra::viewer
