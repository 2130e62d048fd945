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
  // Its window surface goes to the X server directly (shared memory), not through an OpenGL
  // texture: without a GPU that is Mesa's llvmpipe, whose threads and copies cost the frames
  // more than the window's drawing itself (bench/README.md). An environment variable
  // SDL_FRAMEBUFFER_ACCELERATION still decides, as SDL documents.
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
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
    const bool interacting = input_this_frame_ || drag_button_ != 0 || ImGui::IsAnyItemActive();
    requestFrame(interacting);
    takeFrame();
    updateOracle();
    drawIfDue(interacting || imgui_settle_ > 0);
    // --quit-after counts the loop's turns after the script has run to its end (a script
    // waiting for the oracle may take any number of turns).
    const bool script_done = script_next_ == script_.size() && script_wait_frames_ == 0 &&
                             script_wait_passes_ == 0;
    if (script_done) ++window_frames_;
    if (args_.quit_after > 0 && window_frames_ >= args_.quit_after) quit_ = true;
    const bool script_running = !script_done && script_wait_passes_ == 0;
    if (!quit_ && !script_running) waitForWork(interacting || imgui_settle_ > 0);
  }
  saveOnQuit();
  return 0;
}

void ViewerApp::waitForWork(bool interacting) {
  // Each turn of the loop asks the X server for events: several system calls, which cost the
  // renderer more than drawing the window once woken for every frame the worker finishes
  // (bench/README.md). So until the pacer lets the window draw, only an event wakes the loop;
  // then a finished frame does too, to be shown as it arrives.
  const double until_draw = pacer_.untilDue(std::chrono::steady_clock::now(), interacting);
  if (until_draw > 0.0) {
    SDL_WaitEventTimeout(nullptr, std::clamp(int(std::ceil(until_draw)), 1, kIdleWaitMs));
  } else if (frames_->busy()) {
    frames_->waitForFrame(kIdleWaitMs);
  } else {
    SDL_WaitEventTimeout(nullptr, kIdleWaitMs);
  }
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
  // Dear ImGui sees an event at its next frame, and hover or a popup settles a frame later.
  imgui_settle_ = 2;
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
        saveScreenshotNow(fmt::format("out/viewer-{}.png", saved_count_),
                          fmt::format("out/viewer-{}-visibility.exr", saved_count_));
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
  request.context.debug_layers = !overlayLayer(model_.overlay).empty();
  const float scale = preview ? std::clamp(model_.preview_scale, 0.05f, 1.0f) : 1.0f;
  request.width = std::max(1, int(std::lround(model_.width * scale)));
  request.height = std::max(1, int(std::lround(model_.height * scale)));
  if (preview && model_.preview_samples) {
    request.technique = previewConfig(model_, request.preview_options);
  }
  request.preview = preview && (scale < 1.0f || !request.preview_options.empty());
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
  if (model_.compare == CompareMode::Off) {
    oracle_->stop();
    oracle_image_.reset();
    comparison_.reset();
    return;
  }
  // The oracle works on the full-size frame of the current view only.
  if (!have_full_ || full_.generation != model_.generation) {
    comparison_.reset();
    return;
  }
  oracle_->restart(full_.generation, full_.frame, model_.lights, model_.selected_light);
  std::optional<OracleImage> oracle = oracle_->latest();
  if (!oracle || oracle->generation != full_.generation) {
    oracle_image_.reset();
    comparison_.reset();
    return;
  }
  // Compared again only when the oracle has a new pass or the tolerance moved.
  const bool same = oracle_image_ && comparison_ && oracle_image_->passes == oracle->passes &&
                    oracle_image_->generation == oracle->generation &&
                    oracle_image_->light == oracle->light &&
                    compared_tolerance_ == model_.compare_tolerance;
  if (same) return;
  comparison_ = compareWithOracle(*full_.frame, *oracle, model_.compare_tolerance);
  compared_tolerance_ = model_.compare_tolerance;
  oracle_image_ = std::move(oracle);
}

std::string ViewerApp::levelText() const {
  if (!shown_.frame) return "no frame yet";
  const int w = shown_.frame->color.width(), h = shown_.frame->color.height();
  std::string text = shown_.preview ? fmt::format("preview {}x{} (of {}x{})", w, h, model_.width,
                                                  model_.height)
                                    : fmt::format("full {}x{}", w, h);
  if (shown_.preview && !shown_.preview_options.empty()) {
    text += fmt::format(", {}", fmt::join(shown_.preview_options, ", "));
  }
  if (frames_->busy()) text += ", rendering";
  return text;
}

}  // namespace penumbra::viewer
