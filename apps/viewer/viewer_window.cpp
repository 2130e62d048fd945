// Drawing the window: the frame area (the newest frame with its overlay or comparison, scaled
// to the full frame's size) and the panel, each redrawn only when what it shows changed.
#include <algorithm>

#include <SDL.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include "saving.h"
#include "viewer_app.h"
#include "viewer_panel.h"

namespace penumbra::viewer {

namespace {

constexpr SDL_Color kBackground{20, 20, 24, 255};

}  // namespace

std::optional<OracleImage> ViewerApp::shownOracle() const {
  // The comparison needs the oracle of this very frame: the full-size one of the current view.
  const bool comparing = model_.compare != CompareMode::Off && !shown_.preview &&
                         shown_.generation == model_.generation;
  if (!comparing || !oracle_image_ || oracle_image_->generation != shown_.generation) return {};
  return oracle_image_;
}

std::string ViewerApp::textureKey() const {
  const std::optional<OracleImage> oracle = shownOracle();
  return fmt::format("{} {} {} {} {} {}", shown_.sequence, overlayName(model_.overlay),
                     compareModeName(model_.compare), model_.selected_light,
                     oracle ? oracle->passes : -1, model_.heatmap_scale);
}

bool ViewerApp::updateFrameTexture() {
  if (!shown_.frame) return false;
  const std::string key = textureKey();
  if (key == texture_key_) return false;
  const FrameResult& frame = *shown_.frame;
  const int width = frame.color.width(), height = frame.color.height();
  if (texture_ == nullptr || texture_width_ != width || texture_height_ != height) {
    if (texture_ != nullptr) SDL_DestroyTexture(texture_);
    // 32-bit pixels, the window's own layout under X: copied to the window without converting.
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING,
                                 width, height);
    PENUMBRA_CHECK(texture_ != nullptr, "cannot create the frame texture: {}", SDL_GetError());
    SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_NONE);
    texture_width_ = width;
    texture_height_ = height;
  }
  void* pixels = nullptr;
  int pitch = 0;
  PENUMBRA_CHECK(SDL_LockTexture(texture_, nullptr, &pixels, &pitch) == 0,
                 "cannot write the frame texture: {}", SDL_GetError());
  const std::optional<OracleImage> oracle = shownOracle();
  if (oracle && model_.compare == CompareMode::Split) {
    packPixels(splitImage(frame, *oracle), pixels, pitch);
  } else if (oracle && model_.compare == CompareMode::Heatmap) {
    packPixels(heatmapImage(frame, *oracle, model_.heatmap_scale), pixels, pitch);
  } else if (model_.overlay == Overlay::Shaded) {
    shadedPixels(frame, pixels, pitch);
  } else {
    const size_t light = std::min(model_.selected_light, frame.lights.size() - 1);
    packPixels(overlayImage(frame, model_.overlay, light), pixels, pitch);
  }
  SDL_UnlockTexture(texture_);
  texture_key_ = key;
  return true;
}

std::string ViewerApp::overlayNote() const {
  const std::string layer = overlayLayer(model_.overlay);
  if (layer.empty() || !panel_frame_.frame || panel_frame_.frame->lights.empty()) return "";
  const FrameResult& frame = *panel_frame_.frame;
  const size_t light = std::min(model_.selected_light, frame.lights.size() - 1);
  const DebugLayer* found = findDebugLayer(frame.lights[light].debug_layers, layer);
  if (found != nullptr) return found->description;
  return fmt::format("{} publishes no {} layer", currentTechnique(model_).info->name, layer);
}

bool ViewerApp::panelFiguresStale() const {
  if (shown_.sequence != panel_frame_.sequence || levelText() != panel_level_) return true;
  if (comparison_.has_value() != panel_comparison_.has_value()) return true;
  return comparison_ &&
         (comparison_->oracle_passes != panel_comparison_->oracle_passes ||
          comparison_->difference.fraction_over_tolerance !=
              panel_comparison_->difference.fraction_over_tolerance);
}

void ViewerApp::refreshPanelFigures(bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - panel_refreshed_ < kPanelRefresh) return;
  if (!panelFiguresStale()) return;
  panel_frame_ = shown_;
  panel_frame_ms_ = frame_ms_;
  panel_comparison_ = comparison_;
  panel_level_ = levelText();
  panel_refreshed_ = now;
}

bool ViewerApp::drawWindow(bool present, bool force) {
  const bool frame_changed = updateFrameTexture();
  refreshPanelFigures(force);
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  PanelView view;
  view.shown = panel_frame_.frame ? &panel_frame_ : nullptr;
  view.frame_ms = &panel_frame_ms_;
  view.comparison = panel_comparison_;
  view.level = panel_level_;
  view.message = message_;
  view.overlay_note = overlayNote();
  int window_width = 0, window_height = 0;
  SDL_GetWindowSize(window_, &window_width, &window_height);
  const PanelRequests requests = drawPanel(model_, view, float(model_.width),
                                           float(window_width - model_.width),
                                           float(window_height));
  if (!requests.error.empty()) message_ = "error: " + requests.error;
  if (requests.save_screenshot || requests.save_scene) ++saved_count_;
  if (requests.save_screenshot) {
    saveScreenshotNow(fmt::format("out/viewer-{}.png", saved_count_),
                      fmt::format("out/viewer-{}-visibility.exr", saved_count_));
  }
  if (requests.save_scene) saveSceneNow(fmt::format("out/viewer-{}.json", saved_count_));
  ImGui::Render();
  if (imgui_settle_ > 0) --imgui_settle_;
  if (!panel_) {
    panel_ = std::make_unique<PanelCanvas>(renderer_, model_.width, window_width - model_.width,
                                           window_height);
  }
  const bool panel_changed = panel_->update(*ImGui::GetDrawData());
  if (!frame_changed && !panel_changed && !force) return false;  // the window shows this already
  SDL_SetRenderDrawColor(renderer_, kBackground.r, kBackground.g, kBackground.b, kBackground.a);
  const SDL_Rect below_frame{0, model_.height, model_.width, window_height - model_.height};
  SDL_RenderFillRect(renderer_, &below_frame);
  if (texture_ != nullptr) {
    // A preview is stretched over the full frame's area (nearest pixel: no blur to mistake
    // for a penumbra).
    const SDL_Rect area{0, 0, model_.width, model_.height};
    SDL_RenderCopy(renderer_, texture_, nullptr, &area);
  } else {
    const SDL_Rect area{0, 0, model_.width, model_.height};
    SDL_RenderFillRect(renderer_, &area);
  }
  panel_->copyToWindow();
  if (present) SDL_RenderPresent(renderer_);
  return true;
}

bool ViewerApp::drawIfDue(bool interacting) {
  const auto start = std::chrono::steady_clock::now();
  if (!pacer_.due(start, interacting)) return false;
  const bool frame_stale = shown_.frame && textureKey() != texture_key_;
  const bool figures_due = start - panel_refreshed_ >= kPanelRefresh && panelFiguresStale();
  if (!frame_stale && !figures_due && imgui_settle_ == 0 && !interacting) return false;
  if (!drawWindow()) return false;
  pacer_.drew(start, std::chrono::steady_clock::now() - start);
  return true;
}

void ViewerApp::saveWindowNow(const std::string& path) {
  int width = 0, height = 0;
  PENUMBRA_CHECK(SDL_GetRendererOutputSize(renderer_, &width, &height) == 0,
                 "cannot read the window's size: {}", SDL_GetError());
  // Drawn again and read before it is presented (after that the back buffer is undefined),
  // with the oracle's newest figures.
  updateOracle();
  // Twice: Dear ImGui lays out what changed since its last frame (a table's new rows) a frame
  // later.
  drawWindow(false, true);
  drawWindow(false, true);
  Image<glm::u8vec3> pixels(width, height);
  PENUMBRA_CHECK(SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGB24, pixels.data(),
                                      width * 3) == 0,
                 "{}: cannot read the window back: {}", path, SDL_GetError());
  SDL_RenderPresent(renderer_);
  writePngRgb8(path, pixels);
  message_ = "saved " + path;
}

}  // namespace penumbra::viewer
