#include "viewer_app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include <SDL.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include "camera_control.h"
#include "saving.h"
#include "viewer_panel.h"

namespace penumbra::viewer {

namespace {

constexpr size_t kFrameHistory = 120;  // frames in the time plot
constexpr int kIdleWaitMs = 30;        // the loop's sleep when nothing happens

bool insideFrame(int x, int y, int width, int height) {
  return x >= 0 && y >= 0 && x < width && y < height;
}

}  // namespace

ViewerApp::ViewerApp(const ViewerArgs& args) : args_(args) {
  scene_ = loadScene(args.scene);
  base_scene_ = baseSceneName(args.scene);
  model_ = makeViewerModel(scene_, args.technique, args.width, args.height);
  for (const auto& [name, value] : args.technique_options) setOption(model_, name, value);
  model_.threads = args.threads;
  model_.simd = !args.scalar;
  if (!args.script.empty()) script_ = readScript(args.script);
  frames_ = std::make_unique<FrameWorker>(scene_);
  oracle_ = std::make_unique<OracleWorker>(scene_);
  openWindow();
}

ViewerApp::~ViewerApp() {
  // The workers stop before the window goes: nothing renders into a closed window's frames.
  frames_.reset();
  oracle_.reset();
  closeWindow();
}

void ViewerApp::openWindow() {
  PENUMBRA_CHECK(SDL_Init(SDL_INIT_VIDEO) == 0, "cannot open a window: {}", SDL_GetError());
  // Without a display SDL falls back to drivers nobody sees: fine for a run that quits by
  // itself, a window that never shows otherwise.
  const std::string driver = SDL_GetCurrentVideoDriver();
  if ((driver == "offscreen" || driver == "dummy") && args_.quit_after == 0 &&
      args_.bench_frames == 0) {
    SDL_Quit();
    throw Error(fmt::format("no display to open the window on (SDL's video driver is '{}'): set "
                            "DISPLAY, or run it under xvfb-run with --quit-after N",
                            driver));
  }
  const int width = model_.width + panel_width_;
  const int height = std::max(model_.height, 720);
  window_ = SDL_CreateWindow(fmt::format("penumbra view {}", args_.scene).c_str(),
                             SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, 0);
  PENUMBRA_CHECK(window_ != nullptr, "cannot open a window: {}", SDL_GetError());
  // The software renderer works everywhere (Xvfb, no GPU); the frames are CPU images anyway.
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  PENUMBRA_CHECK(renderer_ != nullptr, "cannot create a renderer: {}", SDL_GetError());
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForSDLRenderer(window_);
  ImGui_ImplSDLRenderer_Init(renderer_);
  // A scripted run puts the pointer in the frame area's corner, off the panel, so that what
  // the panel draws (hover highlights) does not depend on where the screen's pointer was.
  if (!script_.empty()) SDL_WarpMouseInWindow(window_, 0, 0);
}

void ViewerApp::closeWindow() {
  if (renderer_ != nullptr) {
    ImGui_ImplSDLRenderer_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
  }
  if (texture_ != nullptr) SDL_DestroyTexture(texture_);
  if (renderer_ != nullptr) SDL_DestroyRenderer(renderer_);
  if (window_ != nullptr) SDL_DestroyWindow(window_);
  SDL_Quit();
}

int ViewerApp::run() {
  if (args_.bench_frames > 0) {
    runBench();
    return 0;
  }
  while (!quit_) {
    input_this_frame_ = false;
    runScript();
    SDL_Event event;
    while (SDL_PollEvent(&event)) handleEvent(event);
    // A slider held down counts as dragging: previews until it is let go.
    requestFrame(input_this_frame_ || drag_button_ != 0 || ImGui::IsAnyItemActive());
    takeFrame();
    updateOracle();
    const auto now = std::chrono::steady_clock::now();
    const auto since_present = now - last_present_;
    if (since_present >= kPresentInterval || input_this_frame_) {
      drawWindow();
      last_present_ = now;
    }
    // --quit-after counts the frames after the script has run to its end (a script waiting
    // for the oracle may take any number of frames).
    const bool script_done = script_next_ == script_.size() && script_wait_frames_ == 0 &&
                             script_wait_passes_ == 0;
    if (script_done) ++window_frames_;
    if (args_.quit_after > 0 && window_frames_ >= args_.quit_after) quit_ = true;
    const bool script_running = !script_done && script_wait_passes_ == 0;
    if (!quit_ && !script_running) {
      // Sleep until the worker delivers or an event comes, not spin: the worker needs the cores.
      // Never past the next presentation, when a frame waits to be shown.
      const int wait_ms = last_present_ == now ? kIdleWaitMs : int(kPresentInterval.count());
      if (frames_->busy()) {
        frames_->waitForFrame(wait_ms);
      } else {
        SDL_WaitEventTimeout(nullptr, wait_ms);
      }
    }
  }
  saveOnQuit();
  return 0;
}

bool ViewerApp::frameAreaEvent(const SDL_Event& event) const {
  switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
      return insideFrame(event.button.x, event.button.y, model_.width, model_.height);
    case SDL_MOUSEBUTTONUP:
      return event.button.button == drag_button_;
    case SDL_MOUSEMOTION:
      return drag_button_ != 0;
    case SDL_MOUSEWHEEL:
      return insideFrame(event.wheel.mouseX, event.wheel.mouseY, model_.width, model_.height);
    default:
      return false;
  }
}

void ViewerApp::handleEvent(const SDL_Event& event) {
  // The frame area's mouse events are the camera's and the lights': the panel never sees them
  // (a scripted drag would otherwise click wherever the panel thinks the pointer is).
  if (!frameAreaEvent(event)) ImGui_ImplSDL2_ProcessEvent(&event);
  const ImGuiIO& io = ImGui::GetIO();
  switch (event.type) {
    case SDL_QUIT:
      quit_ = true;
      break;
    case SDL_KEYDOWN:
    case SDL_KEYUP: {
      const bool down = event.type == SDL_KEYDOWN;
      const SDL_Keycode key = event.key.keysym.sym;
      if (key == SDLK_LCTRL || key == SDLK_RCTRL) ctrl_ = down;
      if (key == SDLK_LSHIFT || key == SDLK_RSHIFT) shift_ = down;
      if (!down || io.WantTextInput) break;
      if (key == SDLK_ESCAPE) quit_ = true;
      if (key == SDLK_l) selectLight(model_, (model_.selected_light + 1) % model_.lights.size());
      if (key == SDLK_s) {
        ++saved_count_;
        saveScreenshotNow(fmt::format("out/viewer-{}.png", saved_count_), "");
        saveSceneNow(fmt::format("out/viewer-{}.json", saved_count_));
      }
      break;
    }
    case SDL_MOUSEBUTTONDOWN:
      if (insideFrame(event.button.x, event.button.y, model_.width, model_.height)) {
        drag_button_ = event.button.button;
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.button == drag_button_) drag_button_ = 0;
      break;
    case SDL_MOUSEMOTION: {
      if (drag_button_ == 0) break;
      const float dx = float(event.motion.xrel), dy = float(event.motion.yrel);
      if (drag_button_ == SDL_BUTTON_LEFT && ctrl_) {
        dragLight(model_.lights[model_.selected_light], model_.camera, dx, dy, model_.height,
                  shift_);
      } else if (drag_button_ == SDL_BUTTON_LEFT) {
        orbitCamera(model_.camera, dx, dy);
      } else {
        panCamera(model_.camera, dx, dy, model_.height);
      }
      ++model_.generation;
      input_this_frame_ = true;
      break;
    }
    case SDL_MOUSEWHEEL:
      if (insideFrame(event.wheel.mouseX, event.wheel.mouseY, model_.width, model_.height)) {
        zoomCamera(model_.camera, event.wheel.preciseY);
        ++model_.generation;
        input_this_frame_ = true;
      }
      break;
    default:
      break;
  }
}

FrameRequest ViewerApp::makeRequest(bool preview) const {
  FrameRequest request;
  request.generation = model_.generation;
  request.camera = model_.camera;
  request.lights = model_.lights;
  request.technique = techniqueConfig(model_);
  request.context.threads = model_.threads;
  request.context.simd = model_.simd;
  const float scale = preview ? std::clamp(model_.preview_scale, 0.05f, 1.0f) : 1.0f;
  request.width = std::max(1, int(std::lround(model_.width * scale)));
  request.height = std::max(1, int(std::lround(model_.height * scale)));
  request.preview = preview && scale < 1.0f;
  return request;
}

void ViewerApp::requestFrame(bool interacting) {
  const bool changed = model_.generation != requested_generation_;
  // While the user drags, previews; once the view rests, the full size of the same view.
  const bool refine = !interacting && requested_preview_;
  if (!changed && !refine) return;
  FrameRequest request = makeRequest(interacting);
  requested_generation_ = request.generation;
  requested_preview_ = request.preview;
  frames_->submit(std::move(request));
}

void ViewerApp::takeFrame() {
  std::optional<DeliveredFrame> delivered = frames_->take();
  if (!delivered) return;
  if (!delivered->error.empty()) {
    message_ = "error: " + delivered->error;
    return;
  }
  if (message_.rfind("error", 0) == 0) message_.clear();
  frame_ms_.push_back(float(delivered->render_ms));
  if (frame_ms_.size() > kFrameHistory) frame_ms_.pop_front();
  shown_ = *delivered;
  if (!delivered->preview) {
    full_ = std::move(*delivered);
    have_full_ = true;
  }
}

void ViewerApp::updateOracle() {
  comparison_.reset();
  if (model_.compare == CompareMode::Off) {
    oracle_->stop();
    return;
  }
  // The oracle works on the full-size frame of the current view only.
  if (!have_full_ || full_.generation != model_.generation) return;
  oracle_->restart(full_.generation, full_.frame, model_.lights, model_.selected_light);
  if (const std::optional<OracleImage> oracle = oracle_->latest()) {
    if (oracle->generation == full_.generation) {
      comparison_ = compareWithOracle(*full_.frame, *oracle, model_.compare_tolerance);
    }
  }
}

std::string ViewerApp::levelText() const {
  if (!shown_.frame) return "no frame yet";
  const int w = shown_.frame->color.width(), h = shown_.frame->color.height();
  std::string text = shown_.preview ? fmt::format("preview {}x{} (of {}x{})", w, h, model_.width,
                                                  model_.height)
                                    : fmt::format("full {}x{}", w, h);
  if (frames_->busy()) text += ", rendering";
  return text;
}

}  // namespace penumbra::viewer
