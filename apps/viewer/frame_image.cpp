#include "frame_image.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace penumbra::viewer {

namespace {

constexpr int kTileLevel = 4;  // 16x16 tiles
const glm::u8vec3 kPenumbraTint{255, 0, 255};

const TechniqueResult& visibilityLight(const FrameResult& frame, size_t light) {
  PENUMBRA_CHECK(light < frame.lights.size(), "light {} is not in the frame ({} lights)", light,
                 frame.lights.size());
  return frame.lights[light];
}

const Image<float>& visibilityOf(const FrameResult& frame, size_t light) {
  return visibilityLight(frame, light).visibility;
}

Image<uint8_t> coveredMask(const FrameResult& frame) {
  const Image<uint32_t>& primitive = frame.eye.primitive;
  Image<uint8_t> mask(primitive.width(), primitive.height(), 0);
  for (size_t i = 0; i < primitive.size(); ++i) {
    mask.data()[i] = primitive.data()[i] != kNoPrimitive ? 1 : 0;
  }
  return mask;
}

uint8_t stretch(float value, float lo, float hi) {
  return unitToByte(hi > lo ? (value - lo) / (hi - lo) : 1.0f);
}

// Linear to sRGB through a table: a pow per channel costs the window more than some frames
// take to render. 4096 steps over [0, 1] put a displayed code at most one off the PNG's (the
// screenshot is the PNG writer's, not this).
uint8_t encodeSrgb8(float linear) {
  constexpr int kSteps = 4096;
  static const std::vector<uint8_t> table = [] {
    std::vector<uint8_t> t(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) t[size_t(i)] = linearToSrgb8(float(i) / kSteps);
    return t;
  }();
  // NaN compares false: it takes code 0, as linearToSrgb8 gives it.
  const float clamped = linear > 0.0f ? std::min(linear, 1.0f) : 0.0f;
  return table[size_t(clamped * kSteps + 0.5f)];
}

uint32_t argb(uint8_t r, uint8_t g, uint8_t b) {
  return 0xFF000000u | uint32_t(r) << 16 | uint32_t(g) << 8 | uint32_t(b);
}

}  // namespace

Rgb8Image shadedImage(const FrameResult& frame) {
  Rgb8Image image(frame.color.width(), frame.color.height());
  for (size_t i = 0; i < image.size(); ++i) {
    const vec3& c = frame.color.data()[i];
    image.data()[i] = glm::u8vec3(encodeSrgb8(c.x), encodeSrgb8(c.y), encodeSrgb8(c.z));
  }
  return image;
}

void shadedPixels(const FrameResult& frame, void* pixels, int pitch) {
  for (int y = 0; y < frame.color.height(); ++y) {
    auto* row = reinterpret_cast<uint32_t*>(static_cast<char*>(pixels) + size_t(y) * pitch);
    for (int x = 0; x < frame.color.width(); ++x) {
      const vec3& c = frame.color.at(x, y);
      row[x] = argb(encodeSrgb8(c.x), encodeSrgb8(c.y), encodeSrgb8(c.z));
    }
  }
}

void packPixels(const Rgb8Image& image, void* pixels, int pitch) {
  for (int y = 0; y < image.height(); ++y) {
    auto* row = reinterpret_cast<uint32_t*>(static_cast<char*>(pixels) + size_t(y) * pitch);
    for (int x = 0; x < image.width(); ++x) {
      const glm::u8vec3 c = image.at(x, y);
      row[x] = argb(c.x, c.y, c.z);
    }
  }
}

Rgb8Image visibilityImage(const FrameResult& frame, size_t light) {
  return visibilityToImage(visibilityOf(frame, light));
}

Rgb8Image penumbraImage(const FrameResult& frame, size_t light) {
  const Image<float>& visibility = visibilityOf(frame, light);
  Rgb8Image image = shadedImage(frame);
  for (size_t i = 0; i < image.size(); ++i) {
    const float v = visibility.data()[i];
    if (v > 0.0f && v < 1.0f) {
      image.data()[i] = glm::u8vec3((glm::uvec3(image.data()[i]) + glm::uvec3(kPenumbraTint)) / 2u);
    }
  }
  return image;
}

Rgb8Image depthImage(const FrameResult& frame) {
  const Image<float>& depth = frame.eye.depth.depth;
  float lo = std::numeric_limits<float>::max(), hi = 0.0f;
  for (size_t i = 0; i < depth.size(); ++i) {
    const float d = depth.data()[i];
    if (d > 0.0f) {  // 0 is the background (reversed-Z: infinity)
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  Rgb8Image image(depth.width(), depth.height());
  for (size_t i = 0; i < depth.size(); ++i) {
    const float d = depth.data()[i];
    const uint8_t g = d > 0.0f ? stretch(d, lo, hi) : 0;
    image.data()[i] = glm::u8vec3(g);
  }
  return image;
}

Rgb8Image tileRangeImage(const FrameResult& frame) {
  const TileDepthRange& tiles = frame.eye.depth.tileRange(kTileLevel);
  float widest = 0.0f;
  for (size_t i = 0; i < tiles.zmin.size(); ++i) {
    widest = std::max(widest, tiles.zmax.data()[i] - tiles.zmin.data()[i]);
  }
  const int w = frame.eye.depth.width(), h = frame.eye.depth.height();
  Rgb8Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int tx = x >> kTileLevel, ty = y >> kTileLevel;
      const float range = tiles.zmax.at(tx, ty) - tiles.zmin.at(tx, ty);
      const bool edge = (x & 15) == 0 || (y & 15) == 0;  // the tile grid
      image.at(x, y) = edge ? glm::u8vec3(40) : errorColor(widest > 0.0f ? range / widest : 0.0f);
    }
  }
  return image;
}

bool frameHasLayer(const FrameResult& frame, size_t light, const std::string& name) {
  return findDebugLayer(visibilityLight(frame, light).debug_layers, name) != nullptr;
}

Rgb8Image debugLayerImage(const FrameResult& frame, size_t light, const std::string& name) {
  Rgb8Image image = shadedImage(frame);
  for (size_t i = 0; i < image.size(); ++i) {
    image.data()[i] = glm::u8vec3(glm::uvec3(image.data()[i]) / 3u);
  }
  const DebugLayer* layer = findDebugLayer(visibilityLight(frame, light).debug_layers, name);
  if (layer == nullptr || layer->values.width() != image.width() ||
      layer->values.height() != image.height()) {
    return image;
  }
  const Image<float>& values = layer->values;
  float largest = 0.0f;
  for (size_t i = 0; i < values.size(); ++i) largest = std::max(largest, values.data()[i]);
  const bool lines = name == kSilhouetteEdgesLayer;
  for (size_t i = 0; i < values.size(); ++i) {
    const float v = values.data()[i];
    if (!(v > 0.0f)) continue;
    image.data()[i] = lines ? glm::u8vec3(255, 230, 0) : errorColor(v / largest);
  }
  return image;
}

Rgb8Image overlayImage(const FrameResult& frame, Overlay overlay, size_t light) {
  switch (overlay) {
    case Overlay::SilhouetteEdges:
    case Overlay::WedgeFootprints:
    case Overlay::CulledTiles: return debugLayerImage(frame, light, overlayLayer(overlay));
    case Overlay::Shaded: return shadedImage(frame);
    case Overlay::Visibility: return visibilityImage(frame, light);
    case Overlay::Penumbra: return penumbraImage(frame, light);
    case Overlay::Depth: return depthImage(frame);
    case Overlay::TileDepthRange: return tileRangeImage(frame);
  }
  return shadedImage(frame);
}

Comparison compareWithOracle(const FrameResult& frame, const OracleImage& oracle,
                             double tolerance) {
  const Image<uint8_t> mask = coveredMask(frame);
  Comparison comparison;
  comparison.difference =
      compareImages(visibilityOf(frame, oracle.light), oracle.visibility, tolerance, &mask);
  comparison.oracle_rays = oracle.rays;
  comparison.oracle_passes = oracle.passes;
  return comparison;
}

Rgb8Image splitImage(const FrameResult& frame, const OracleImage& oracle) {
  Rgb8Image left = visibilityImage(frame, oracle.light);
  const Rgb8Image right = visibilityToImage(oracle.visibility);
  const int middle = left.width() / 2;
  for (int y = 0; y < left.height(); ++y) {
    for (int x = middle; x < left.width(); ++x) {
      left.at(x, y) = x == middle ? glm::u8vec3(255, 200, 0) : right.at(x, y);
    }
  }
  return left;
}

Rgb8Image heatmapImage(const FrameResult& frame, const OracleImage& oracle, float scale) {
  return diffHeatmap(visibilityOf(frame, oracle.light), oracle.visibility, std::max(scale, 1e-6f));
}

}  // namespace penumbra::viewer
