#pragma once
// A headless OpenGL 4.5 core context on Mesa's software rasterizer llvmpipe, through EGL's
// surfaceless platform (no window system, no GPU: the peer must measure llvmpipe and nothing
// else, so the context refuses any other renderer).
#include <string>

namespace penumbra {

class HeadlessGl {
 public:
  // Sets LIBGL_ALWAYS_SOFTWARE, GALLIUM_DRIVER=llvmpipe, EGL_PLATFORM=surfaceless and
  // LP_NUM_THREADS=threads (Mesa reads them once, at display initialisation, so they must be set
  // before), then creates and makes current the context. Throws penumbra::Error on failure,
  // including when the renderer is not llvmpipe.
  explicit HeadlessGl(int threads);
  ~HeadlessGl();
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;

  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& version() const { return version_; }    // GL_VERSION

 private:
  void create(int threads);
  void release();

  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string renderer_;
  std::string version_;
};

}  // namespace penumbra
