// Drawing the window: the frame area (the newest frame with its overlay or comparison, scaled
// to the full frame's size) and the panel.
#include <SDL.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include "saving.h"
#include "viewer_app.h"
#include "viewer_panel.h"

namespace penumbra::viewer {

void ViewerApp::showFrame() {
  if (!shown_.frame) return;
  const FrameResult& frame = *shown_.frame;
  // The comparison needs the oracle of this very frame: the full-size one of the current view.
  std::optional<OracleImage> oracle;
  const bool comparing = model_.compare != CompareMode::Off && !shown_.preview &&
                         shown_.generation == model_.generation;
  if (comparing) oracle = oracle_->latest();
  if (oracle && oracle->generation != shown_.generation) oracle.reset();
  const std::string key = fmt::format(
      "{} {} {} {} {} {}", overlayName(model_.overlay), compareModeName(model_.compare),
      model_.selected_light, oracle ? oracle->passes : -1, model_.heatmap_scale,
      static_cast<const void*>(&frame));
  if (texture_frame_ == &frame && key == texture_key_) return;
  Rgb8Image image;
  if (oracle && model_.compare == CompareMode::Split) {
    image = splitImage(frame, *oracle);
  } else if (oracle && model_.compare == CompareMode::Heatmap) {
    image = heatmapImage(frame, *oracle, model_.heatmap_scale);
  } else {
    image = overlayImage(frame, model_.overlay,
                         std::min(model_.selected_light, frame.lights.size() - 1));
  }
  if (texture_ == nullptr || texture_width_ != image.width() || texture_height_ != image.height()) {
    if (texture_ != nullptr) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING,
                                 image.width(), image.height());
    PENUMBRA_CHECK(texture_ != nullptr, "cannot create the frame texture: {}", SDL_GetError());
    texture_width_ = image.width();
    texture_height_ = image.height();
  }
  static_assert(sizeof(glm::u8vec3) == 3, "the texture takes packed RGB bytes");
  SDL_UpdateTexture(texture_, nullptr, image.data(), image.width() * 3);
  texture_frame_ = &frame;
  texture_key_ = key;
}

void ViewerApp::drawWindow(bool present) {
  showFrame();
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  PanelView view;
  view.shown = shown_.frame ? &shown_ : nullptr;
  view.frame_ms = &frame_ms_;
  view.comparison = comparison_;
  view.level = levelText();
  view.message = message_;
  int window_width = 0, window_height = 0;
  SDL_GetWindowSize(window_, &window_width, &window_height);
  const PanelRequests requests = drawPanel(model_, view, float(model_.width),
                                           float(window_width - model_.width),
                                           float(window_height));
  if (!requests.error.empty()) message_ = "error: " + requests.error;
  if (requests.save_screenshot || requests.save_scene) ++saved_count_;
  if (requests.save_screenshot) saveScreenshotNow(fmt::format("out/viewer-{}.png", saved_count_), "");
  if (requests.save_scene) saveSceneNow(fmt::format("out/viewer-{}.json", saved_count_));
  // The level of detail, over the frame's corner.
  ImGui::GetForegroundDrawList()->AddText(ImVec2(6, 4), IM_COL32(255, 255, 0, 255),
                                          levelText().c_str());
  ImGui::Render();
  SDL_SetRenderDrawColor(renderer_, 20, 20, 24, 255);
  SDL_RenderClear(renderer_);
  if (texture_ != nullptr) {
    // A preview is stretched over the full frame's area (nearest pixel: no blur to mistake
    // for a penumbra).
    const SDL_Rect area{0, 0, model_.width, model_.height};
    SDL_RenderCopy(renderer_, texture_, nullptr, &area);
  }
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
  if (present) SDL_RenderPresent(renderer_);
}

void ViewerApp::saveWindowNow(const std::string& path) {
  int width = 0, height = 0;
  PENUMBRA_CHECK(SDL_GetRendererOutputSize(renderer_, &width, &height) == 0,
                 "cannot read the window's size: {}", SDL_GetError());
  // Drawn again and read before it is presented (after that the back buffer is undefined),
  // with the oracle's newest figures.
  updateOracle();
  drawWindow(false);
  Image<glm::u8vec3> pixels(width, height);
  PENUMBRA_CHECK(SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGB24, pixels.data(),
                                      width * 3) == 0,
                 "{}: cannot read the window back: {}", path, SDL_GetError());
  SDL_RenderPresent(renderer_);
  writePngRgb8(path, pixels);
  message_ = "saved " + path;
}

}  // namespace penumbra::viewer
