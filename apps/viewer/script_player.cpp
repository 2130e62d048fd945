// Replaying a script (input_script.h): mouse and key commands become SDL events, processed by
// the window like the user's; panel commands set the model as the panel's controls do.
#include <SDL.h>
#include <fmt/format.h>

#include "viewer_app.h"

namespace penumbra::viewer {

namespace {

int parseArgInt(const ScriptCommand& command, size_t i, int min, int max) {
  return int(parseInteger(command.args.at(i), min, max,
                          fmt::format("line {}: {}", command.line, command.name)));
}

float parseArgFloat(const ScriptCommand& command, size_t i) {
  return float(parseNumber(command.args.at(i), -1e6, 1e6,
                           fmt::format("line {}: {}", command.line, command.name)));
}

void pushKey(SDL_Keycode key, bool down) {
  SDL_Event event{};
  event.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  event.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  event.key.keysym.sym = key;
  event.key.keysym.scancode = SDL_GetScancodeFromKey(key);
  SDL_PushEvent(&event);
}

void pushButton(Uint8 button, int x, int y, bool down) {
  SDL_Event event{};
  event.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
  event.button.button = button;
  event.button.state = down ? SDL_PRESSED : SDL_RELEASED;
  event.button.clicks = 1;
  event.button.x = x;
  event.button.y = y;
  SDL_PushEvent(&event);
}

void pushMotion(int x, int y, int dx, int dy) {
  SDL_Event event{};
  event.type = SDL_MOUSEMOTION;
  event.motion.x = x;
  event.motion.y = y;
  event.motion.xrel = dx;
  event.motion.yrel = dy;
  SDL_PushEvent(&event);
}

Uint8 buttonNamed(const ScriptCommand& command) {
  const std::string& name = command.args[0];
  if (name == "left") return SDL_BUTTON_LEFT;
  if (name == "middle") return SDL_BUTTON_MIDDLE;
  if (name == "right") return SDL_BUTTON_RIGHT;
  throw Error(
      fmt::format("line {}: unknown button '{}' (left, middle, right)", command.line, name));
}

}  // namespace

void ViewerApp::pushDrag(const ScriptCommand& command) {
  const Uint8 button = buttonNamed(command);
  const int x0 = parseArgInt(command, 1, -100000, 100000),
            y0 = parseArgInt(command, 2, -100000, 100000);
  const int x1 = parseArgInt(command, 3, -100000, 100000),
            y1 = parseArgInt(command, 4, -100000, 100000);
  int steps = 8;
  bool ctrl = false, shift = false;
  for (size_t i = 5; i < command.args.size(); ++i) {
    const std::string& word = command.args[i];
    if (word == "ctrl") ctrl = true;
    else if (word == "shift") shift = true;
    else steps = parseArgInt(command, i, 1, 1000);
  }
  if (ctrl) pushKey(SDLK_LCTRL, true);
  if (shift) pushKey(SDLK_LSHIFT, true);
  pushButton(button, x0, y0, true);
  int x = x0, y = y0;
  for (int k = 1; k <= steps; ++k) {
    // Whole pixels, as a mouse reports them; the steps add up to exactly (x1 - x0, y1 - y0).
    const int nx = x0 + (x1 - x0) * k / steps, ny = y0 + (y1 - y0) * k / steps;
    pushMotion(nx, ny, nx - x, ny - y);
    x = nx;
    y = ny;
  }
  pushButton(button, x1, y1, false);
  if (shift) pushKey(SDLK_LSHIFT, false);
  if (ctrl) pushKey(SDLK_LCTRL, false);
}

void ViewerApp::settle() {
  // The events the script pushed before this command take effect first, and the frame of the
  // resulting view is there to be saved or shown.
  SDL_Event event;
  while (SDL_PollEvent(&event)) handleEvent(event);
  waitForFullFrame();
  shown_ = full_;
}

void ViewerApp::runScript() {
  if (script_wait_frames_ > 0) {
    --script_wait_frames_;
    return;
  }
  if (script_wait_passes_ > 0) {
    const std::optional<OracleImage> oracle = oracle_->latest();
    if (!oracle || oracle->generation != model_.generation ||
        oracle->passes < script_wait_passes_) {
      return;
    }
    script_wait_passes_ = 0;
  }
  while (script_next_ < script_.size() && script_wait_frames_ == 0 && script_wait_passes_ == 0) {
    const ScriptCommand& command = script_[script_next_++];
    try {
      runScriptCommand(command);
    } catch (const Error& e) {
      throw Error(fmt::format("{}:{}: {}", args_.script, command.line, e.what()));
    }
  }
}

void ViewerApp::runScriptCommand(const ScriptCommand& command) {
  const std::string& name = command.name;
  const auto arg = [&](size_t i) -> const std::string& { return command.args.at(i); };
  if (name == "wait") {
    script_wait_frames_ = parseArgInt(command, 0, 0, 1000000);
  } else if (name == "wait-oracle") {
    PENUMBRA_CHECK(model_.compare != CompareMode::Off, "wait-oracle needs compare mode on");
    script_wait_passes_ = parseArgInt(command, 0, 1, OracleWorker::kMaxPasses);
  } else if (name == "drag") {
    pushDrag(command);
  } else if (name == "wheel") {
    SDL_Event event{};
    event.type = SDL_MOUSEWHEEL;
    event.wheel.y = parseArgInt(command, 0, -100, 100);
    event.wheel.preciseY = float(event.wheel.y);
    event.wheel.mouseX = parseArgInt(command, 1, -100000, 100000);
    event.wheel.mouseY = parseArgInt(command, 2, -100000, 100000);
    SDL_PushEvent(&event);
  } else if (name == "key") {
    const SDL_Keycode key = SDL_GetKeyFromName(arg(0).c_str());
    PENUMBRA_CHECK(key != SDLK_UNKNOWN, "unknown key '{}'", arg(0));
    pushKey(key, true);
    pushKey(key, false);
  } else if (name == "technique") {
    selectTechnique(model_, arg(0));
  } else if (name == "option") {
    setOption(model_, arg(0), arg(1));
  } else if (name == "light") {
    selectLight(model_, size_t(parseArgInt(command, 0, 0, 1 << 20)));
  } else if (name == "light-radius") {
    setLightRadius(model_, parseArgFloat(command, 0));
  } else if (name == "light-intensity") {
    setLightIntensity(model_, parseArgFloat(command, 0));
  } else if (name == "overlay") {
    setOverlay(model_, parseOverlay(arg(0)));
  } else if (name == "compare") {
    model_.compare = parseCompareMode(arg(0));
  } else if (name == "preview-samples") {
    model_.preview_samples = parseFlag(arg(0), "preview-samples");
  } else if (name == "preview-scale") {
    model_.preview_scale = std::clamp(parseArgFloat(command, 0), 0.05f, 1.0f);
  } else if (name == "threads") {
    model_.threads = parseArgInt(command, 0, 0, 1024);
    ++model_.generation;
  } else if (name == "simd") {
    model_.simd = parseFlag(arg(0), "simd");
    ++model_.generation;
  } else if (name == "save-scene") {
    settle();
    saveSceneNow(arg(0));
  } else if (name == "screenshot") {
    settle();
    saveScreenshotNow(arg(0), "");
  } else if (name == "window-screenshot") {
    settle();
    saveWindowNow(arg(0));
  }
}

}  // namespace penumbra::viewer
