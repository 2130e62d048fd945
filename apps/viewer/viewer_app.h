#pragma once
// The viewer's window and loop: SDL2 with its software-capable renderer, Dear ImGui for the
// panel. Every window frame it replays the script's next commands, handles input, asks the
// frame worker for a frame when the model changed (a preview while the user drags, the full
// size when the view rests), shows the newest frame with its overlay or comparison, and draws
// the panel.
#include <chrono>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <penumbra/penumbra.h>

#include "frame_image.h"
#include "frame_worker.h"
#include "input_script.h"
#include "oracle_worker.h"
#include "viewer_args.h"
#include "viewer_model.h"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;
union SDL_Event;

namespace penumbra::viewer {

// The window is drawn at most this often (a 60 Hz display's rate): frames that arrive faster
// are rendered but not all shown, so drawing the window never takes the cores from rendering.
inline constexpr std::chrono::milliseconds kPresentInterval{16};

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerArgs& args);
  ~ViewerApp();
  ViewerApp(const ViewerApp&) = delete;
  ViewerApp& operator=(const ViewerApp&) = delete;
  int run();

 private:
  void openWindow();
  void closeWindow();
  void handleEvent(const SDL_Event& event);
  bool frameAreaEvent(const SDL_Event& event) const;
  void runScript();
  void runScriptCommand(const ScriptCommand& command);
  void pushDrag(const ScriptCommand& command);
  void settle();
  void requestFrame(bool interacting);
  void takeFrame();
  void updateOracle();
  void showFrame();
  void drawWindow(bool present = true);
  FrameRequest makeRequest(bool preview) const;
  const DeliveredFrame& waitForFullFrame();  // of the current generation
  void saveOnQuit();
  void saveScreenshotNow(const std::string& png, const std::string& exr);
  void saveSceneNow(const std::string& path);
  void saveWindowNow(const std::string& path);
  void runBench();
  std::string levelText() const;

  ViewerArgs args_;
  Scene scene_;
  std::string base_scene_;
  ViewerModel model_;
  std::unique_ptr<FrameWorker> frames_;
  std::unique_ptr<OracleWorker> oracle_;

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  int texture_width_ = 0, texture_height_ = 0;
  int panel_width_ = 380;

  // What the window shows: the newest delivered frame, and the newest full-size one.
  DeliveredFrame shown_;
  DeliveredFrame full_;
  bool have_full_ = false;
  uint64_t requested_generation_ = ~uint64_t(0);
  bool requested_preview_ = false;
  std::deque<float> frame_ms_;
  std::optional<Comparison> comparison_;
  std::string message_;
  // What the texture holds, so it is rebuilt only when that changes.
  const FrameResult* texture_frame_ = nullptr;
  std::string texture_key_;

  // Input.
  int drag_button_ = 0;  // SDL button held since a press inside the frame area, 0: none
  bool ctrl_ = false, shift_ = false;
  bool input_this_frame_ = false;
  bool quit_ = false;
  long window_frames_ = 0;
  std::chrono::steady_clock::time_point last_present_{};

  // Script replay.
  std::vector<ScriptCommand> script_;
  size_t script_next_ = 0;
  int script_wait_frames_ = 0;
  int script_wait_passes_ = 0;
  int saved_count_ = 0;
};

}  // namespace penumbra::viewer
