#include "headless_gl.h"

#include <cstdlib>
#include <cstring>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "core/error.h"

namespace penumbra {
namespace {

bool hasToken(const char* list, const char* token) {
  if (!list) return false;
  const size_t n = std::strlen(token);
  for (const char* p = list; (p = std::strstr(p, token)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

std::string glString(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? std::string(s) : std::string("?");
}

}  // namespace

HeadlessGl::HeadlessGl(int threads) {
  try {
    create(threads);
  } catch (...) {
    release();  // the destructor does not run for a constructor that throws
    throw;
  }
}

void HeadlessGl::create(int threads) {
  PENUMBRA_CHECK(threads >= 0, "llvmpipe peer: --threads {} must be >= 0", threads);
  // Overwrite whatever the caller's environment says: --threads is the peer's interface, and a
  // stray GALLIUM_DRIVER=zink would silently measure something else.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  setenv("EGL_PLATFORM", "surfaceless", 1);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  PENUMBRA_CHECK(hasToken(client_extensions, "EGL_EXT_platform_base") &&
                     hasToken(client_extensions, "EGL_MESA_platform_surfaceless"),
                 "llvmpipe peer: EGL lacks EGL_MESA_platform_surfaceless (client extensions: {}); "
                 "install Mesa's EGL (libegl-mesa0)",
                 client_extensions ? client_extensions : "none");
  EGLDisplay display =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  PENUMBRA_CHECK(display != EGL_NO_DISPLAY, "llvmpipe peer: no surfaceless EGL display");
  EGLint major = 0, minor = 0;
  PENUMBRA_CHECK(eglInitialize(display, &major, &minor),
                 "llvmpipe peer: eglInitialize failed (0x{:x})", eglGetError());
  display_ = display;
  PENUMBRA_CHECK(eglBindAPI(EGL_OPENGL_API), "llvmpipe peer: EGL has no desktop OpenGL");

  // The peer renders into its own framebuffer object, so the config only has to allow a
  // desktop GL context; surfaceless contexts need no surface at all.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                      EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  PENUMBRA_CHECK(eglChooseConfig(display, config_attributes, &config, 1, &config_count) &&
                     config_count > 0,
                 "llvmpipe peer: no EGL config for desktop OpenGL");
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                       EGL_CONTEXT_MINOR_VERSION, 5,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  PENUMBRA_CHECK(context != EGL_NO_CONTEXT,
                 "llvmpipe peer: no OpenGL 4.5 core context (EGL error 0x{:x})", eglGetError());
  context_ = context;
  PENUMBRA_CHECK(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context),
                 "llvmpipe peer: eglMakeCurrent without a surface failed (0x{:x})",
                 eglGetError());

  renderer_ = glString(GL_RENDERER);
  version_ = glString(GL_VERSION);
  PENUMBRA_CHECK(renderer_.find("llvmpipe") != std::string::npos,
                 "llvmpipe peer: the renderer is '{}', not llvmpipe", renderer_);
  PENUMBRA_CHECK(epoxy_gl_version() >= 45, "llvmpipe peer: '{}' gives OpenGL {}, 4.5 is needed",
                 renderer_, version_);
}

HeadlessGl::~HeadlessGl() { release(); }

void HeadlessGl::release() {
  auto display = static_cast<EGLDisplay>(display_);
  if (context_) {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
  }
  if (display) eglTerminate(display);
  context_ = nullptr;
  display_ = nullptr;
}

}  // namespace penumbra
