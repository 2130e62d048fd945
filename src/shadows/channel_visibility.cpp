// setChannelVisibility (shadows/technique.h): a textured light's per-channel visibility and
// its radiance-weighted mean, the fraction of the light's power that reaches the point.
#include "core/error.h"
#include "core/parallel.h"
#include "shadows/technique.h"

namespace penumbra {

void setChannelVisibility(TechniqueResult& result, const Light& light,
                          ChannelVisibility channels) {
  const int width = channels[0].width(), height = channels[0].height();
  for (const Image<float>& c : channels) {
    PENUMBRA_CHECK(c.width() == width && c.height() == height,
                   "channel visibilities of different sizes ({}x{} and {}x{})", width, height,
                   c.width(), c.height());
  }
  const vec3 radiance = lightRadiance(light);
  const float total = radiance.x + radiance.y + radiance.z;
  // A black light (colour or intensity 0) weighs the channels alike: no power either way.
  const vec3 weight = total > 0.0f ? radiance / total : vec3(1.0f / 3.0f);
  result.visibility.resizeForOverwrite(width, height);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    const float* r = channels[0].row(y);
    const float* g = channels[1].row(y);
    const float* b = channels[2].row(y);
    float* out = result.visibility.row(y);
    for (int x = 0; x < width; ++x) out[x] = (weight.x * r[x] + weight.y * g[x]) + weight.z * b[x];
  });
  result.channels = std::move(channels);
}

}  // namespace penumbra
