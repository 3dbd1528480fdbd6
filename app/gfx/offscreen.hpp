// Rendering without a display: a headless EGL context, the renderer, a multisampled render target
// and, optionally, Dear ImGui drawn headlessly on top (its OpenGL backend with no platform
// backend: a fixed display size and time step). Used by `render`, the chart images of `compare`,
// and the golden-image tests.
#pragma once

#include <functional>
#include <memory>
#include <span>

#include "draw/frame.hpp"
#include "gfx/headless_context.hpp"
#include "gfx/render_target.hpp"
#include "gfx/renderer.hpp"
#include "io/png.hpp"

namespace springlab::gfx {

class Offscreen {
 public:
  // `ui_scale` > 0 sets up Dear ImGui at that scale; 0 leaves it out.
  Offscreen(bool software, int width, int height, float ui_scale, double fps = 60.0);
  ~Offscreen();

  // Draws the frame, then whatever `ui` draws with ImGui (between NewFrame and Render), and
  // reads the result back.
  void render(const draw::Frame& frame, const std::function<void()>& ui, app::Image& out);
  // The same in two halves, so that the caller can work while the rasteriser's threads draw
  // (Mesa's llvmpipe starts on glFlush): draw() returns at once, read() waits for the pixels.
  // With `bottom_up` the rows are left as GL reads them (out.bottom_up), sparing a copy.
  void draw(std::span<const draw::Frame> frames, const std::function<void()>& ui);
  void draw(const draw::Frame& frame, const std::function<void()>& ui) {
    draw(std::span(&frame, 1), ui);
  }
  void read(app::Image& out, bool bottom_up = false);

  std::string renderer_name() const { return context_.renderer(); }
  int samples() const { return target_.samples(); }

 private:
  HeadlessContext context_;
  std::unique_ptr<Renderer> renderer_;
  RenderTarget target_;
  int width_, height_;
  bool imgui_ = false;
  double fps_;
};

}  // namespace springlab::gfx
