#include "shadows/reference/embree_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/error.h"

namespace penumbra {
namespace {

// Embree reports errors through a callback on the thread that made the failing call, and keeps
// an error code per thread. Throwing from inside the callback would unwind through Embree's C
// API, so the callback only records the message and checkDevice() throws afterwards.
thread_local std::string t_embree_message;

void recordError(void*, RTCError code, const char* message) {
  t_embree_message = fmt::format("{} (code {})", message ? message : "no message", int(code));
}

void checkDevice(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE) {
    throw Error(fmt::format("Embree failed to {}: {}", what,
                            t_embree_message.empty() ? fmt::format("code {}", int(code))
                                                     : t_embree_message));
  }
}

// One device for the process: creating one starts Embree's thread pool and costs milliseconds,
// which every test would pay. C++ makes the initialisation of a function-local static
// thread-safe; if it throws, the next call tries again. Never released (lives until exit).
RTCDevice sharedDevice() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (d == nullptr) {
      throw Error(fmt::format("Embree could not create a device (error code {})",
                              int(rtcGetDeviceError(nullptr))));
    }
    rtcSetDeviceErrorFunction(d, recordError, nullptr);
    return d;
  }();
  return device;
}

RTCScene handle(void* scene) { return static_cast<RTCScene>(scene); }

void addMesh(RTCDevice device, RTCScene scene, const Mesh& mesh) {
  const size_t triangles = mesh.triangleCount();
  PENUMBRA_CHECK(mesh.indices.size() % 3 == 0, "mesh '{}' has {} indices, not a multiple of 3",
                 mesh.name, mesh.indices.size());
  if (triangles == 0) return;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    PENUMBRA_CHECK(isFinite(mesh.positions[i]), "mesh '{}' vertex {} is not finite", mesh.name,
                   i);
  }
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    PENUMBRA_CHECK(mesh.indices[i] < mesh.positions.size(),
                   "mesh '{}' index {} is {} but the mesh has {} vertices", mesh.name, i,
                   mesh.indices[i], mesh.positions.size());
  }

  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  checkDevice(device, "create a triangle geometry");
  // Copies, not shared buffers: Embree reads vertices with 16-byte loads, so the buffer needs
  // 4 bytes of padding past the last float3, which a std::vector<vec3> does not promise.
  const size_t vertex_bytes = mesh.positions.size() * sizeof(float) * 3;
  RTCBuffer vertices = rtcNewBuffer(device, vertex_bytes + 16);
  RTCBuffer indices = rtcNewBuffer(device, mesh.indices.size() * sizeof(uint32_t));
  if (vertices == nullptr || indices == nullptr) {
    if (vertices) rtcReleaseBuffer(vertices);
    if (indices) rtcReleaseBuffer(indices);
    rtcReleaseGeometry(geometry);
    checkDevice(device, "allocate mesh buffers");
    throw Error(fmt::format("Embree could not allocate buffers for mesh '{}'", mesh.name));
  }
  auto* v = static_cast<float*>(rtcGetBufferData(vertices));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    v[3 * i + 0] = mesh.positions[i].x;
    v[3 * i + 1] = mesh.positions[i].y;
    v[3 * i + 2] = mesh.positions[i].z;
  }
  std::memset(reinterpret_cast<char*>(v) + vertex_bytes, 0, 16);
  std::memcpy(rtcGetBufferData(indices), mesh.indices.data(),
              mesh.indices.size() * sizeof(uint32_t));
  rtcSetGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0,
                       sizeof(float) * 3, mesh.positions.size());
  rtcSetGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0,
                       sizeof(uint32_t) * 3, triangles);
  rtcReleaseBuffer(vertices);  // the geometry holds its own references
  rtcReleaseBuffer(indices);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  checkDevice(device, fmt::format("add mesh '{}'", mesh.name).c_str());
}

// Embree marks an occluded ray by setting its tfar to -infinity.
bool isBlocked(float tfar) { return tfar == -std::numeric_limits<float>::infinity(); }

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene) {
  RTCDevice device = sharedDevice();
  RTCScene s = rtcNewScene(device);
  checkDevice(device, "create a scene");
  scene_ = s;
  try {
    // Robust mode: watertight triangle tests, so a ray through a shared edge or a vertex hits
    // one of the triangles there instead of slipping between them. High quality: the oracle
    // traces hundreds of rays per pixel, so a better BVH pays for its build time.
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    for (const Mesh& mesh : scene.meshes) addMesh(device, s, mesh);
    rtcCommitScene(s);
    checkDevice(device, "build the scene BVH");
  } catch (...) {
    rtcReleaseScene(s);
    scene_ = nullptr;
    throw;
  }
}

EmbreeScene::~EmbreeScene() {
  if (scene_ != nullptr) rtcReleaseScene(handle(scene_));
}

void EmbreeScene::occluded(const ShadowRay* rays, size_t count, bool packets,
                           uint8_t* blocked) const {
  RTCScene s = handle(scene_);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (!packets) {
    for (size_t i = 0; i < count; ++i) {
      RTCRay ray;
      ray.org_x = rays[i].origin.x;
      ray.org_y = rays[i].origin.y;
      ray.org_z = rays[i].origin.z;
      ray.tnear = 0.0f;
      ray.dir_x = rays[i].direction.x;
      ray.dir_y = rays[i].direction.y;
      ray.dir_z = rays[i].direction.z;
      ray.time = 0.0f;
      ray.tfar = rays[i].tfar;
      ray.mask = ~0u;
      ray.id = 0;
      ray.flags = 0;
      rtcOccluded1(s, &context, &ray);
      blocked[i] = isBlocked(ray.tfar) ? 1 : 0;
    }
    return;
  }
  // The caller's rays in one batch share an origin or a target (a pixel's rays to the light, a
  // row's rays to the light centre), so they travel together through the BVH.
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  constexpr size_t kPacket = 16;
  for (size_t first = 0; first < count; first += kPacket) {
    const size_t n = std::min(kPacket, count - first);
    alignas(64) int valid[kPacket];
    RTCRay16 packet;
    for (size_t k = 0; k < kPacket; ++k) {
      const ShadowRay& r = rays[first + std::min(k, n - 1)];  // idle lanes repeat the last ray
      valid[k] = k < n ? -1 : 0;
      packet.org_x[k] = r.origin.x;
      packet.org_y[k] = r.origin.y;
      packet.org_z[k] = r.origin.z;
      packet.tnear[k] = 0.0f;
      packet.dir_x[k] = r.direction.x;
      packet.dir_y[k] = r.direction.y;
      packet.dir_z[k] = r.direction.z;
      packet.time[k] = 0.0f;
      packet.tfar[k] = r.tfar;
      packet.mask[k] = ~0u;
      packet.id[k] = 0;
      packet.flags[k] = 0;
    }
    rtcOccluded16(valid, s, &context, &packet);
    for (size_t k = 0; k < n; ++k) blocked[first + k] = isBlocked(packet.tfar[k]) ? 1 : 0;
  }
}

}  // namespace penumbra
