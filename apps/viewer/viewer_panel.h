#pragma once
// The side panel (Dear ImGui): technique list and each technique's options drawn from its
// option table, the lights, the frame settings, overlays and compare mode, the frame's timings
// and counters, and the save buttons. It edits the model; what it cannot do itself (saving)
// it asks for.
#include <deque>
#include <optional>
#include <string>

#include "frame_image.h"
#include "frame_worker.h"
#include "viewer_model.h"

namespace penumbra::viewer {

struct PanelView {
  const DeliveredFrame* shown = nullptr;  // the frame on screen, if any
  const std::deque<float>* frame_ms = nullptr;  // the last frames' render times, oldest first
  std::optional<Comparison> comparison;
  std::string level;    // "full 640x427" or "preview 1/2 (320x213)"
  std::string message;  // the last error or saved file
  std::string overlay_note;  // what the debug layer shown counts, or that there is none
};

struct PanelRequests {
  bool save_screenshot = false;
  bool save_scene = false;
  std::string error;  // a control was set to a value the technique refuses
};

PanelRequests drawPanel(ViewerModel& model, const PanelView& view, float x, float width,
                        float height);

}  // namespace penumbra::viewer
