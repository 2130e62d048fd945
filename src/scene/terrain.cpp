#include <cmath>
#include <vector>

#include "core/error.h"
#include "scene/generators.h"
#include "scene/hash.h"
#include "scene/mesh_ops.h"
#include "scene/normals.h"

namespace penumbra {

Mesh makeFractalTerrain(int level, float half_size, float roughness, uint32_t seed) {
  PENUMBRA_CHECK(level >= 1 && level <= 10, "fractal: level {} must be in 1..10", level);
  PENUMBRA_CHECK(half_size > 0.0f && std::isfinite(half_size), "fractal: half size {} must be > 0",
                 half_size);
  PENUMBRA_CHECK(roughness > 0.0f && roughness <= 1.0f, "fractal: roughness {} must be in (0, 1]",
                 roughness);
  const int n = 1 << level;  // cells per side
  const int stride = n + 1;
  std::vector<float> height(size_t(stride) * size_t(stride), 0.0f);
  auto h = [&](int x, int z) -> float& { return height[size_t(z) * size_t(stride) + size_t(x)]; };
  // Every grid point is displaced exactly once, by a hash of its coordinates: the result does
  // not depend on visiting order and is the same on every platform.
  auto jitter = [&](int x, int z, float amplitude) {
    return amplitude * signedUnit(hashCoords(seed, uint32_t(x), uint32_t(z)));
  };

  float amplitude = 0.5f * half_size * roughness;
  for (int step = n; step > 1; step /= 2) {
    const int half = step / 2;
    // Diamond step: square centres from their four corners.
    for (int z = half; z < n; z += step) {
      for (int x = half; x < n; x += step) {
        h(x, z) = 0.25f * (h(x - half, z - half) + h(x + half, z - half) + h(x - half, z + half) +
                           h(x + half, z + half)) +
                  jitter(x, z, amplitude);
      }
    }
    // Square step: edge midpoints from their (three or four) diamond neighbours.
    for (int z = 0; z <= n; z += half) {
      for (int x = (z / half) % 2 == 0 ? half : 0; x <= n; x += step) {
        float sum = 0.0f;
        int count = 0;
        auto add = [&](int nx, int nz) {
          if (nx < 0 || nx > n || nz < 0 || nz > n) return;
          sum += h(nx, nz);
          ++count;
        };
        add(x - half, z);
        add(x + half, z);
        add(x, z - half);
        add(x, z + half);
        h(x, z) = sum / float(count) + jitter(x, z, amplitude);
      }
    }
    amplitude *= roughness;
  }
  double mean = 0.0;
  for (float value : height) mean += value;
  mean /= double(height.size());

  Mesh mesh;
  mesh.name = "fractal";
  mesh.positions.reserve(height.size());
  const float cell = 2.0f * half_size / float(n);
  for (int z = 0; z <= n; ++z) {
    for (int x = 0; x <= n; ++x) {
      mesh.positions.push_back(
          vec3(-half_size + cell * float(x), h(x, z) - float(mean), -half_size + cell * float(z)));
    }
  }
  mesh.indices.reserve(size_t(n) * size_t(n) * 6);
  for (int z = 0; z < n; ++z) {
    for (int x = 0; x < n; ++x) {
      const uint32_t a = uint32_t(z * stride + x), b = a + uint32_t(stride);  // b: one step in +z
      const uint32_t c = b + 1, d = a + 1;
      // (+z) x (+x) = +y: both triangles face up.
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
  finishMesh(mesh, 180.0f);  // smooth everywhere: a landscape has no intended creases
  return mesh;
}

}  // namespace penumbra
