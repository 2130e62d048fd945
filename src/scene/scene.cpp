#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/flatten_instances.h"
#include "scene/normals.h"

namespace penumbra {

namespace {

bool nonNegativeFinite(const vec3& v) {
  return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

std::string sceneLabel(const Scene& scene) {
  return scene.name.empty() ? std::string("scene") : fmt::format("scene '{}'", scene.name);
}

void checkMesh(const Scene& scene, size_t m, Mesh& mesh) {
  const std::string label = fmt::format("{}: mesh {} ('{}')", sceneLabel(scene), m, mesh.name);
  PENUMBRA_CHECK(mesh.indices.size() % 3 == 0, "{}: {} indices is not a whole number of triangles",
                 label, mesh.indices.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const vec3& p = mesh.positions[i];
    PENUMBRA_CHECK(isFinite(p), "{}: vertex {} has a non-finite position ({}, {}, {})", label, i,
                   p.x, p.y, p.z);
  }
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    PENUMBRA_CHECK(mesh.indices[i] < mesh.positions.size(),
                   "{}: triangle {} references vertex {} but the mesh has {} vertices", label,
                   i / 3, mesh.indices[i], mesh.positions.size());
  }
  PENUMBRA_CHECK(mesh.material < scene.materials.size(),
                 "{}: material index {} is out of range (the scene has {} materials)", label,
                 mesh.material, scene.materials.size());
  PENUMBRA_CHECK(mesh.corner_normals.empty() || mesh.corner_normals.size() == mesh.indices.size(),
                 "{}: {} corner normals for {} corners", label, mesh.corner_normals.size(),
                 mesh.indices.size());
  // Shading normals are optional for meshes built in code; shadows never read them.
  if (mesh.corner_normals.empty()) computeCornerNormals(mesh);
}

}  // namespace

std::pair<uint32_t, uint32_t> Scene::locateTriangle(uint32_t global_id) const {
  PENUMBRA_DCHECK(triangle_offsets.size() == meshes.size() + 1);
  PENUMBRA_DCHECK(global_id < triangle_offsets.back());
  // The last mesh whose first triangle is <= global_id; empty meshes share their successor's
  // offset and are skipped by upper_bound.
  const auto it = std::upper_bound(triangle_offsets.begin(), triangle_offsets.end() - 1, global_id);
  const uint32_t mesh = uint32_t(it - triangle_offsets.begin()) - 1;
  return {mesh, global_id - triangle_offsets[mesh]};
}

void Scene::finalize() {
  const std::string label = sceneLabel(*this);
  PENUMBRA_CHECK(!materials.empty(), "{} has no materials (at least one is needed)", label);
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& m = materials[i];
    PENUMBRA_CHECK(nonNegativeFinite(m.albedo) && nonNegativeFinite(m.specular),
                   "{}: material {} ('{}'): albedo and specular must be finite and >= 0", label, i,
                   m.name);
    PENUMBRA_CHECK(std::isfinite(m.shininess) && m.shininess >= 0.0f,
                   "{}: material {} ('{}'): shininess {} must be finite and >= 0", label, i, m.name,
                   m.shininess);
  }

  PENUMBRA_CHECK(!lights.empty(), "{} has no lights", label);
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& l = lights[i];
    PENUMBRA_CHECK(isFinite(l.center), "{}: light {}: centre ({}, {}, {}) is not finite", label, i,
                   l.center.x, l.center.y, l.center.z);
    PENUMBRA_CHECK(std::isfinite(l.radius) && l.radius >= 0.0f,
                   "{}: light {}: radius {} must be finite and >= 0", label, i, l.radius);
    PENUMBRA_CHECK(nonNegativeFinite(l.color), "{}: light {}: colour must be finite and >= 0",
                   label, i);
    PENUMBRA_CHECK(std::isfinite(l.intensity) && l.intensity >= 0.0f,
                   "{}: light {}: intensity {} must be finite and >= 0", label, i, l.intensity);
    try {
      checkLightShape(l);  // a disk's normal, a rectangle's edges (light.h)
    } catch (const Error& e) {
      throw Error(fmt::format("{}: light {}: {}", label, i, e.what()));
    }
  }

  PENUMBRA_CHECK(settings.width > 0 && settings.height > 0 && settings.width <= 8192 &&
                     settings.height <= 8192,
                 "{}: image size {}x{} must be between 1x1 and 8192x8192", label, settings.width,
                 settings.height);
  PENUMBRA_CHECK(nonNegativeFinite(settings.ambient) && nonNegativeFinite(settings.background),
                 "{}: ambient and background colours must be finite and >= 0", label);
  try {
    (void)camera.makeView(settings.width, settings.height);
    checkScenePath(*this);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", label, e.what()));
  }

  try {
    flattenInstances(*this);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", label, e.what()));
  }
  triangle_offsets.assign(1, 0);
  size_t total = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    checkMesh(*this, m, meshes[m]);
    total += meshes[m].triangleCount();
    PENUMBRA_CHECK(total < std::numeric_limits<uint32_t>::max(),
                   "{} has more than 2^32 - 1 triangles", label);
    triangle_offsets.push_back(uint32_t(total));
  }
  PENUMBRA_CHECK(total > 0, "{} has no triangles", label);

  adjacency.clear();
  adjacency.reserve(meshes.size());
  for (Mesh& mesh : meshes) adjacency.push_back(buildEdges(mesh));
}

}  // namespace penumbra
