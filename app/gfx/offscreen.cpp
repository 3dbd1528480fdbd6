#include "gfx/offscreen.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "ui/theme.hpp"

namespace springlab::gfx {

Offscreen::Offscreen(bool software, int width, int height, float ui_scale, double fps)
    : context_(software),
      renderer_(std::make_unique<Renderer>()),
      width_(width),
      height_(height),
      fps_(fps) {
  target_.resize(width, height, 4);
  if (ui_scale > 0.0f) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ui::apply_theme(ui_scale);
    io.Fonts->Build();  // now: the lesson band measures its text before the first frame is drawn
    ImGui_ImplOpenGL3_Init("#version 330 core");
    imgui_ = true;
  }
}

Offscreen::~Offscreen() {
  if (imgui_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
  }
}

void Offscreen::render(const draw::Frame& frame, const std::function<void()>& ui, app::Image& out) {
  draw(frame, ui);
  read(out);
}

void Offscreen::draw(std::span<const draw::Frame> frames, const std::function<void()>& ui) {
  target_.bind_for_drawing();
  renderer_->draw(frames, width_, height_);
  if (imgui_ && ui) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
    io.DeltaTime = static_cast<float>(1.0 / fps_);
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    // Two passes: Dear ImGui measures a window that appears (or resizes to fit) on its first
    // frame and shows it from the second, and an output frame must not depend on which frames
    // before it were drawn. The first pass only measures.
    for (int pass = 0; pass < 2; ++pass) {
      ImGui_ImplOpenGL3_NewFrame();
      ImGui::NewFrame();
      ui();
      ImGui::Render();
    }
    target_.bind_for_drawing();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  target_.resolve();
  glFlush();
}

void Offscreen::read(app::Image& out, bool bottom_up) {
  out.width = width_;
  out.height = height_;
  out.bottom_up = bottom_up;
  target_.read_rgba(out.rgba, bottom_up);
}

}  // namespace springlab::gfx
