#pragma once
// The panel in a texture of its own, rasterized again only when Dear ImGui's draw data
// changed. SDL's software renderer rasterizes the panel's thousands of small triangles on the
// CPU: redrawn at every window draw, that cost a core's worth of the frames' time (README,
// Viewer). Kept, the panel costs one copy of its pixels per window draw.
#include <string>

struct SDL_Renderer;
struct SDL_Texture;
struct ImDrawData;

namespace penumbra::viewer {

class PanelCanvas {
 public:
  // The panel's rectangle in the window: x in [left, left + width), y in [0, height).
  PanelCanvas(SDL_Renderer* renderer, int left, int width, int height);
  ~PanelCanvas();
  PanelCanvas(const PanelCanvas&) = delete;
  PanelCanvas& operator=(const PanelCanvas&) = delete;

  // Rasterizes `draw_data` into the texture when its bytes differ from the last rasterized
  // ones; true when it did. The draw data's vertices are moved to the texture's origin.
  bool update(ImDrawData& draw_data);
  // Copies the texture into its place in the window.
  void copyToWindow() const;

 private:
  SDL_Renderer* renderer_;
  SDL_Texture* texture_ = nullptr;
  int left_, width_, height_;
  std::string last_bytes_;  // the draw data last rasterized, as drawDataBytes writes it
  std::string bytes_;       // this update's, kept to reuse its memory
};

// Everything that decides the panel's pixels (vertices, indices, and each command's clip
// rectangle, texture and ranges), appended to `out` (cleared first).
void drawDataBytes(const ImDrawData& draw_data, std::string& out);

}  // namespace penumbra::viewer
