#pragma once
// The viewer's window and loop: SDL2 with its software-capable renderer, Dear ImGui for the
// panel. Every turn of the loop it replays the script's next commands, handles input, asks the
// frame worker for a frame when the model changed (a preview while the user drags, the full
// size when the view rests), and, when what the window shows changed and the pacer allows
// (present_pacer.h), draws the newest frame with its overlay or comparison beside the panel.
// The panel keeps its own texture (panel_canvas.h), and its figures refresh a few times a
// second: an unchanged panel costs a copy, not a rasterization.
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
#include "panel_canvas.h"
#include "present_pacer.h"
#include "viewer_args.h"
#include "viewer_model.h"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;
union SDL_Event;

namespace penumbra::viewer {

// How often the panel's figures (timings, counters, the level, the oracle's error) follow the
// frames: readable, and the panel is rasterized again only this often while nobody touches it.
inline constexpr std::chrono::milliseconds kPanelRefresh{250};

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
  std::optional<OracleImage> shownOracle() const;  // the oracle of the shown frame, if any
  std::string textureKey() const;                   // what the texture should hold
  bool updateFrameTexture();                        // true when the texture changed
  bool panelFiguresStale() const;
  std::string overlayNote() const;
  void refreshPanelFigures(bool force);
  // Runs the panel and draws the window if anything in it changed (or `force`); presents it
  // unless `present` is false (a window screenshot reads it first). True when it drew.
  bool drawWindow(bool present = true, bool force = false);
  bool drawIfDue(bool interacting);  // true when it drew
  void waitForWork(bool interacting);
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
  std::unique_ptr<PanelCanvas> panel_;
  PresentPacer pacer_;

  // What the window shows: the newest delivered frame, and the newest full-size one.
  DeliveredFrame shown_;
  DeliveredFrame full_;
  bool have_full_ = false;
  uint64_t requested_generation_ = ~uint64_t(0);
  bool requested_preview_ = false;
  std::deque<float> frame_ms_;
  std::optional<OracleImage> oracle_image_;  // of the full frame of the current view
  std::optional<Comparison> comparison_;     // the frame against oracle_image_
  float compared_tolerance_ = -1.0f;         // the tolerance comparison_ used
  std::string message_;
  // What the texture holds (the frame's sequence number, overlay, comparison), so it is
  // converted only when that changes.
  std::string texture_key_;
  // The panel's figures as last refreshed (kPanelRefresh).
  DeliveredFrame panel_frame_;
  std::deque<float> panel_frame_ms_;
  std::optional<Comparison> panel_comparison_;
  std::string panel_level_;
  std::chrono::steady_clock::time_point panel_refreshed_{};
  int imgui_settle_ = 0;  // window draws still owed to Dear ImGui after an event

  // Input.
  int drag_button_ = 0;  // SDL button held since a press inside the frame area, 0: none
  bool ctrl_ = false, shift_ = false;
  bool input_this_frame_ = false;
  bool quit_ = false;
  long window_frames_ = 0;

  // Script replay.
  std::vector<ScriptCommand> script_;
  size_t script_next_ = 0;
  int script_wait_frames_ = 0;
  int script_wait_passes_ = 0;
  int saved_count_ = 0;
};

}  // namespace penumbra::viewer
