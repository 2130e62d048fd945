#include "peer_renderer.h"

#include <chrono>
#include <cstddef>

#include <epoxy/gl.h>
#include <meshoptimizer.h>

#include "core/error.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {
namespace {

constexpr int kMaxMaterials = 256;  // the std140 material block below holds this many

// `invariant` on every vertex shader: the light caps and the lit pass must land on exactly the
// eye pass's depth (the lit pass tests GL_EQUAL, a light cap must fail GL_GREATER on the surface
// it comes from), so the compiler may not contract or reorder the position maths differently in
// different programs. All three programs compute view_projection * vec4(p, 1) from the same floats.
constexpr const char* kSceneVertexShader = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in uint a_material;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
flat out uint v_material;
invariant gl_Position;
void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_material = a_material;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

constexpr const char* kMaterialBlock = R"(
layout(std140, binding = 0) uniform Materials {
  vec4 albedo[256];
  vec4 specular_shininess[256];  // rgb specular, a Blinn-Phong exponent
};
)";

constexpr const char* kAmbientFragmentShader = R"(
in vec3 v_world;
in vec3 v_normal;
flat in uint v_material;
uniform vec3 u_ambient;
out vec4 o_color;
void main() { o_color = vec4(u_ambient * albedo[v_material].rgb, 1.0); }
)";

// render/shading.cpp's light term: no distance falloff, nothing where N.L <= 0, the normal turned
// towards the eye on two-sided (open) meshes.
constexpr const char* kLitFragmentShader = R"(
in vec3 v_world;
in vec3 v_normal;
flat in uint v_material;
uniform vec3 u_light;
uniform vec3 u_light_color;
uniform vec3 u_eye;
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = normalize(u_light - v_world);
  float n_dot_l = dot(n, l);
  vec3 h = normalize(l + normalize(u_eye - v_world));
  vec4 s = specular_shininess[v_material];
  vec3 reflected = albedo[v_material].rgb * n_dot_l + s.rgb * pow(max(dot(n, h), 0.0), s.a);
  o_color = vec4(n_dot_l > 0.0 ? reflected * u_light_color : vec3(0.0), 0.0);
}
)";

// A w = 0 vertex goes to the point at infinity away from the light (Everitt & Kilgard section
// 4); w = 1 vertices are passed through untouched (a select, not arithmetic, to stay identical).
constexpr const char* kVolumeVertexShader = R"(#version 450 core
layout(location = 0) in vec4 a_position;
uniform mat4 u_view_projection;
uniform vec3 u_light;
invariant gl_Position;
void main() {
  vec3 p = a_position.w == 0.0 ? a_position.xyz - u_light : a_position.xyz;
  gl_Position = u_view_projection * vec4(p, a_position.w);
}
)";

constexpr const char* kVolumeFragmentShader = R"(#version 450 core
void main() {}
)";

GLuint compileShader(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    glDeleteShader(shader);
    throw Error(fmt::format("llvmpipe peer: shader does not compile: {}", log));
  }
  return shader;
}

GLuint linkProgram(const std::string& vertex, const std::string& fragment) {
  const GLuint vs = compileShader(GL_VERTEX_SHADER, vertex);
  const GLuint fs = compileShader(GL_FRAGMENT_SHADER, fragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof(log), nullptr, log);
    glDeleteProgram(program);
    throw Error(fmt::format("llvmpipe peer: program does not link: {}", log));
  }
  return program;
}

void checkGl(const char* where) {
  const GLenum error = glGetError();
  PENUMBRA_CHECK(error == GL_NO_ERROR, "llvmpipe peer: OpenGL error 0x{:x} {}", error, where);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// One corner of the eye pass's vertex buffer; equal corners are merged (meshoptimizer).
struct SceneVertex {
  float position[3];
  float normal[3];
  uint32_t material;
};
static_assert(sizeof(SceneVertex) == 28, "SceneVertex must be tightly packed for the remap");

}  // namespace

struct PeerRenderer::Gl {
  GLuint framebuffer = 0;
  GLuint color = 0;
  GLuint depth_stencil = 0;
  GLuint scene_vao = 0;
  GLuint scene_vertices = 0;
  GLuint scene_indices = 0;
  GLuint materials = 0;
  GLuint volume_vao = 0;
  GLuint volume_vertices = 0;
  GLuint volume_indices = 0;  // streamed every light of every frame
  GLuint ambient_program = 0;
  GLuint lit_program = 0;
  GLuint volume_program = 0;
  GLint ambient_view_projection = -1, ambient_color = -1;
  GLint lit_view_projection = -1, lit_light = -1, lit_light_color = -1, lit_eye = -1;
  GLint volume_view_projection = -1, volume_light = -1;

  ~Gl() {
    glDeleteProgram(ambient_program);
    glDeleteProgram(lit_program);
    glDeleteProgram(volume_program);
    const GLuint buffers[] = {scene_vertices, scene_indices, materials, volume_vertices,
                              volume_indices};
    glDeleteBuffers(5, buffers);
    glDeleteVertexArrays(1, &scene_vao);
    glDeleteVertexArrays(1, &volume_vao);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &color);
    glDeleteRenderbuffers(1, &depth_stencil);
  }
};

PeerRenderer::PeerRenderer(const Scene& scene, const PeerOptions& options)
    : scene_(scene), options_(options), gl_(std::make_unique<Gl>()) {
  PENUMBRA_CHECK(scene.materials.size() <= size_t(kMaxMaterials),
                 "llvmpipe peer: scene '{}' has {} materials, at most {} fit the shader's block",
                 scene.name, scene.materials.size(), kMaxMaterials);
  view_ = scene.camera.makeView(options.width, options.height);
  volume_meshes_ = prepareVolumeMeshes(scene);
  volume_far_offset_ = volumeVertexCount(scene);
  scene_triangles_ = scene.triangleCount();
  Gl& gl = *gl_;

  const std::string header = "#version 450 core\n";
  gl.ambient_program =
      linkProgram(kSceneVertexShader, header + kMaterialBlock + kAmbientFragmentShader);
  gl.lit_program = linkProgram(kSceneVertexShader, header + kMaterialBlock + kLitFragmentShader);
  gl.volume_program = linkProgram(kVolumeVertexShader, kVolumeFragmentShader);
  gl.ambient_view_projection = glGetUniformLocation(gl.ambient_program, "u_view_projection");
  gl.ambient_color = glGetUniformLocation(gl.ambient_program, "u_ambient");
  gl.lit_view_projection = glGetUniformLocation(gl.lit_program, "u_view_projection");
  gl.lit_light = glGetUniformLocation(gl.lit_program, "u_light");
  gl.lit_light_color = glGetUniformLocation(gl.lit_program, "u_light_color");
  gl.lit_eye = glGetUniformLocation(gl.lit_program, "u_eye");
  gl.volume_view_projection = glGetUniformLocation(gl.volume_program, "u_view_projection");
  gl.volume_light = glGetUniformLocation(gl.volume_program, "u_light");

  // Eye-pass geometry: closed meshes first (back faces culled), then open ones (two-sided), as
  // raster/eye_pass.h draws them. Corners are merged where position, normal and material agree,
  // and each range is reordered for the post-transform vertex cache: what a competent engine
  // ships, and what spares llvmpipe's single-threaded vertex stage.
  std::vector<SceneVertex> corners;
  corners.reserve(scene_triangles_ * 3);
  for (bool closed_pass : {true, false}) {
    for (const Mesh& mesh : scene.meshes) {
      if (mesh.closed != closed_pass) continue;
      PENUMBRA_CHECK(mesh.corner_normals.size() == mesh.indices.size(),
                     "llvmpipe peer: mesh '{}' has no corner normals", mesh.name);
      for (size_t i = 0; i < mesh.indices.size(); ++i) {
        const vec3& p = mesh.positions[mesh.indices[i]];
        const vec3& n = mesh.corner_normals[i];
        corners.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}, mesh.material});
      }
      (closed_pass ? closed_index_count_ : open_index_count_) += uint32_t(mesh.indices.size());
    }
  }
  std::vector<uint32_t> remap(corners.size());
  scene_vertices_ = meshopt_generateVertexRemap(remap.data(), nullptr, corners.size(),
                                                corners.data(), corners.size(),
                                                sizeof(SceneVertex));
  std::vector<SceneVertex> vertices(scene_vertices_);
  meshopt_remapVertexBuffer(vertices.data(), corners.data(), corners.size(), sizeof(SceneVertex),
                            remap.data());
  std::vector<uint32_t> indices(corners.size());
  meshopt_remapIndexBuffer(indices.data(), nullptr, corners.size(), remap.data());
  meshopt_optimizeVertexCache(indices.data(), indices.data(), closed_index_count_,
                              scene_vertices_);
  meshopt_optimizeVertexCache(indices.data() + closed_index_count_,
                              indices.data() + closed_index_count_, open_index_count_,
                              scene_vertices_);

  glCreateBuffers(1, &gl.scene_vertices);
  glNamedBufferStorage(gl.scene_vertices, GLsizeiptr(vertices.size() * sizeof(SceneVertex)),
                       vertices.data(), 0);
  glCreateBuffers(1, &gl.scene_indices);
  glNamedBufferStorage(gl.scene_indices, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                       indices.data(), 0);
  glCreateVertexArrays(1, &gl.scene_vao);
  glVertexArrayVertexBuffer(gl.scene_vao, 0, gl.scene_vertices, 0, sizeof(SceneVertex));
  glVertexArrayElementBuffer(gl.scene_vao, gl.scene_indices);
  glEnableVertexArrayAttrib(gl.scene_vao, 0);
  glVertexArrayAttribFormat(gl.scene_vao, 0, 3, GL_FLOAT, GL_FALSE,
                            offsetof(SceneVertex, position));
  glVertexArrayAttribBinding(gl.scene_vao, 0, 0);
  glEnableVertexArrayAttrib(gl.scene_vao, 1);
  glVertexArrayAttribFormat(gl.scene_vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(SceneVertex, normal));
  glVertexArrayAttribBinding(gl.scene_vao, 1, 0);
  glEnableVertexArrayAttrib(gl.scene_vao, 2);
  glVertexArrayAttribIFormat(gl.scene_vao, 2, 1, GL_UNSIGNED_INT,
                             offsetof(SceneVertex, material));
  glVertexArrayAttribBinding(gl.scene_vao, 2, 0);

  std::vector<vec4> material_block(2 * kMaxMaterials, vec4(0.0f));
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    material_block[i] = vec4(m.albedo, 1.0f);
    material_block[kMaxMaterials + i] = vec4(m.specular, m.shininess);
  }
  glCreateBuffers(1, &gl.materials);
  glNamedBufferStorage(gl.materials, GLsizeiptr(material_block.size() * sizeof(vec4)),
                       material_block.data(), 0);

  const std::vector<float> volume_vertices = volumeVertices(scene);
  glCreateBuffers(1, &gl.volume_vertices);
  glNamedBufferStorage(gl.volume_vertices, GLsizeiptr(volume_vertices.size() * sizeof(float)),
                       volume_vertices.data(), 0);
  glCreateBuffers(1, &gl.volume_indices);
  glCreateVertexArrays(1, &gl.volume_vao);
  glVertexArrayVertexBuffer(gl.volume_vao, 0, gl.volume_vertices, 0, 4 * sizeof(float));
  glVertexArrayElementBuffer(gl.volume_vao, gl.volume_indices);
  glEnableVertexArrayAttrib(gl.volume_vao, 0);
  glVertexArrayAttribFormat(gl.volume_vao, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(gl.volume_vao, 0, 0);

  glCreateRenderbuffers(1, &gl.color);
  glNamedRenderbufferStorage(gl.color, GL_RGBA8, options.width, options.height);
  glCreateRenderbuffers(1, &gl.depth_stencil);
  glNamedRenderbufferStorage(
      gl.depth_stencil,
      options.depth == DepthFormat::kDepth32FStencil8 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8,
      options.width, options.height);
  glCreateFramebuffers(1, &gl.framebuffer);
  glNamedFramebufferRenderbuffer(gl.framebuffer, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gl.color);
  glNamedFramebufferRenderbuffer(gl.framebuffer, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                 gl.depth_stencil);
  PENUMBRA_CHECK(glCheckNamedFramebufferStatus(gl.framebuffer, GL_FRAMEBUFFER) ==
                     GL_FRAMEBUFFER_COMPLETE,
                 "llvmpipe peer: the {}x{} framebuffer is incomplete", options.width,
                 options.height);

  // Fixed state for every frame.
  glBindFramebuffer(GL_FRAMEBUFFER, gl.framebuffer);
  glViewport(0, 0, options.width, options.height);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, gl.materials);
  const mat4& vp = view_.view_projection;
  glProgramUniformMatrix4fv(gl.ambient_program, gl.ambient_view_projection, 1, GL_FALSE, &vp[0][0]);
  glProgramUniformMatrix4fv(gl.lit_program, gl.lit_view_projection, 1, GL_FALSE, &vp[0][0]);
  glProgramUniformMatrix4fv(gl.volume_program, gl.volume_view_projection, 1, GL_FALSE, &vp[0][0]);
  glProgramUniform3fv(gl.ambient_program, gl.ambient_color, 1, &scene.settings.ambient[0]);
  glProgramUniform3fv(gl.lit_program, gl.lit_eye, 1, &view_.eye[0]);
  const vec3& background = scene.settings.background;
  glClearColor(background.x, background.y, background.z, 1.0f);
  glClearDepthf(0.0f);  // reversed-Z: 0 is infinitely far
  glClearStencil(0);
  glBlendFunc(GL_ONE, GL_ONE);
  checkGl("while setting up the scene");
}

PeerRenderer::~PeerRenderer() = default;

PeerFrameStats PeerRenderer::renderFrame() {
  Gl& gl = *gl_;
  PeerFrameStats stats;
  auto start = std::chrono::steady_clock::now();
  const auto drawScene = [&] {
    // Closed meshes back-face culled, open ones two-sided (raster/eye_pass.h).
    glEnable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(closed_index_count_), GL_UNSIGNED_INT, nullptr);
    glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(open_index_count_), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(size_t(closed_index_count_) * sizeof(uint32_t)));
  };

  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(gl.scene_vao);
  glUseProgram(gl.ambient_program);
  drawScene();
  if (options_.pass_breakdown) {
    glFinish();
    stats.eye_ms = millisecondsSince(start);
  }

  for (size_t l = 0; l < scene_.lights.size(); ++l) {
    const Light& light = scene_.lights[l];
    auto volumes_start = std::chrono::steady_clock::now();
    volume_indices_.clear();
    for (size_t m = 0; m < scene_.meshes.size(); ++m) {
      const Silhouette silhouette =
          findSilhouette(scene_.meshes[m], scene_.adjacency[m], light.center);
      appendVolume(scene_.meshes[m], scene_.adjacency[m], volume_meshes_[m], silhouette,
                   light.center, options_.casters, volume_far_offset_, volume_indices_);
    }
    const std::vector<uint32_t>& outward = volume_indices_.outward;
    const std::vector<uint32_t>& flipped = volume_indices_.flipped;
    const size_t outward_bytes = outward.size() * sizeof(uint32_t);
    const size_t flipped_bytes = flipped.size() * sizeof(uint32_t);
    // Orphan and refill: the driver never waits on the previous light's indices.
    glNamedBufferData(gl.volume_indices, GLsizeiptr(outward_bytes + flipped_bytes), nullptr,
                      GL_STREAM_DRAW);
    if (outward_bytes)
      glNamedBufferSubData(gl.volume_indices, 0, GLsizeiptr(outward_bytes), outward.data());
    if (flipped_bytes)
      glNamedBufferSubData(gl.volume_indices, GLintptr(outward_bytes), GLsizeiptr(flipped_bytes),
                           flipped.data());

    if (l > 0) glClear(GL_STENCIL_BUFFER_BIT);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    // Z-fail (Everitt & Kilgard section 3): count the volume faces behind the visible surface,
    // +1 for those facing away from the eye (leaving the volume), -1 for those facing it.
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    glBindVertexArray(gl.volume_vao);
    glUseProgram(gl.volume_program);
    glUniform3fv(gl.volume_light, 1, &light.center[0]);
    glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(outward.size()), GL_UNSIGNED_INT, nullptr);
    if (!flipped.empty()) {
      glFrontFace(GL_CW);
      glDrawElements(GL_TRIANGLES, GLsizei(flipped.size()), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(outward_bytes));
      glFrontFace(GL_CCW);
    }
    if (options_.pass_breakdown) {
      glFinish();
      stats.volumes_ms += millisecondsSince(volumes_start);
    }

    auto shading_start = std::chrono::steady_clock::now();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDepthFunc(GL_EQUAL);
    glEnable(GL_BLEND);
    glBindVertexArray(gl.scene_vao);
    glUseProgram(gl.lit_program);
    const vec3 light_color = light.color * light.intensity;
    glUniform3fv(gl.lit_light, 1, &light.center[0]);
    glUniform3fv(gl.lit_light_color, 1, &light_color[0]);
    drawScene();
    glDisable(GL_BLEND);
    glDepthFunc(GL_GREATER);
    if (options_.pass_breakdown) {
      glFinish();
      stats.shading_ms += millisecondsSince(shading_start);
    }

    stats.silhouette_edges += volume_indices_.silhouette_edges;
    stats.side_quads += volume_indices_.side_quads;
    stats.cap_triangles += volume_indices_.cap_triangles;
    stats.volume_triangles += volume_indices_.triangleCount();
  }
  glFinish();
  checkGl("during the frame");
  return stats;
}

Image<vec3> PeerRenderer::readColor() const {
  const int w = options_.width, h = options_.height;
  std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  checkGl("reading the colour buffer back");
  Image<vec3> out(w, h);
  for (int y = 0; y < h; ++y) {
    // GL's row 0 is the bottom of the picture (GL_LOWER_LEFT), Image's the top.
    const uint8_t* row = rgba.data() + size_t(h - 1 - y) * size_t(w) * 4;
    for (int x = 0; x < w; ++x)
      out.at(x, y) = vec3(row[4 * x], row[4 * x + 1], row[4 * x + 2]) * (1.0f / 255.0f);
  }
  return out;
}

}  // namespace penumbra
