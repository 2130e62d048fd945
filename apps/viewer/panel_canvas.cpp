#include "panel_canvas.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdlrenderer.h>

#include <penumbra/core/error.h>

namespace penumbra::viewer {

namespace {

template <class T>
void appendBytes(std::string& out, const T* data, size_t count) {
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

}  // namespace

void drawDataBytes(const ImDrawData& draw_data, std::string& out) {
  out.clear();
  for (int i = 0; i < draw_data.CmdListsCount; ++i) {
    const ImDrawList& list = *draw_data.CmdLists[i];
    appendBytes(out, list.VtxBuffer.Data, size_t(list.VtxBuffer.Size));
    appendBytes(out, list.IdxBuffer.Data, size_t(list.IdxBuffer.Size));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      appendBytes(out, &cmd.ClipRect, 1);
      appendBytes(out, &cmd.TextureId, 1);
      appendBytes(out, &cmd.VtxOffset, 1);
      appendBytes(out, &cmd.IdxOffset, 1);
      appendBytes(out, &cmd.ElemCount, 1);
    }
    // A list boundary, so that the same bytes split differently do not compare equal.
    const int sizes[2] = {list.VtxBuffer.Size, list.CmdBuffer.Size};
    appendBytes(out, sizes, 2);
  }
}

PanelCanvas::PanelCanvas(SDL_Renderer* renderer, int left, int width, int height)
    : renderer_(renderer), left_(left), width_(width), height_(height) {
  texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_TARGET,
                               width_, height_);
  PENUMBRA_CHECK(texture_ != nullptr, "cannot create the panel's texture: {}", SDL_GetError());
  // Copied over the window, not blended: the panel's pixels are opaque.
  SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_NONE);
}

PanelCanvas::~PanelCanvas() { SDL_DestroyTexture(texture_); }

bool PanelCanvas::update(ImDrawData& draw_data) {
  drawDataBytes(draw_data, bytes_);
  if (bytes_ == last_bytes_) return false;
  std::swap(bytes_, last_bytes_);
  // The backend subtracts DisplayPos from clip rectangles only: the vertices move by hand.
  const ImVec2 origin(float(left_), 0.0f);
  for (int i = 0; i < draw_data.CmdListsCount; ++i) {
    for (ImDrawVert& vertex : draw_data.CmdLists[i]->VtxBuffer) {
      vertex.pos.x -= origin.x;
      vertex.pos.y -= origin.y;
    }
  }
  draw_data.DisplayPos = origin;
  draw_data.DisplaySize = ImVec2(float(width_), float(height_));
  SDL_SetRenderTarget(renderer_, texture_);
  SDL_SetRenderDrawColor(renderer_, 20, 20, 24, 255);
  SDL_RenderClear(renderer_);
  ImGui_ImplSDLRenderer_RenderDrawData(&draw_data);
  SDL_SetRenderTarget(renderer_, nullptr);
  return true;
}

void PanelCanvas::copyToWindow() const {
  const SDL_Rect place{left_, 0, width_, height_};
  SDL_RenderCopy(renderer_, texture_, nullptr, &place);
}

}  // namespace penumbra::viewer
