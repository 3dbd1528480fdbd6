#include "window/window_app.hpp"

// GL through epoxy first, then GLFW without its own GL header.
#include "gfx/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "draw/scene_frame.hpp"
#include "gfx/headless_context.hpp"
#include "gfx/render_target.hpp"
#include "gfx/renderer.hpp"
#include "io/png.hpp"
#include "springlab/error.hpp"
#include "ui/actions.hpp"
#include "ui/compare_panel.hpp"
#include "ui/interaction.hpp"
#include "ui/overlay.hpp"
#include "ui/panels.hpp"
#include "ui/theme.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace {

using Clock = std::chrono::steady_clock;
std::string g_glfw_error;

// One scene on screen: its session and what the panels remember about it.
struct Shown {
  std::unique_ptr<Session> session;
  ui::UiState ui;
  ui::ComparePanel accuracy;
  std::optional<std::string> dropped;  // a file dropped on the window, to open
};

void show(Shown& shown, Prepared p, float scale, const std::string& name, bool background) {
  const std::vector<std::string> scenes = shipped_scenes();
  const auto compare = shown.ui.compare_choice;
  const bool presentation = shown.ui.presentation;
  shown.session = std::make_unique<Session>(std::move(p.scene), p.settings, 60.0);
  // Interactive: stability analyses on a worker thread, the frame loop never waiting for one.
  // Scripted (--frames): made where needed, so that the same run gives the same frames.
  shown.session->set_background_analysis(background);
  ui::UiState ui;
  ui.scale = scale;
  ui.view = draw::ViewOptions::for_scene(shown.session->scene());
  ui.ranges = ui::Ranges::of(*shown.session);
  ui.scenes = scenes;
  ui.scene_name = name;
  ui.compare_choice = compare;
  ui.presentation = presentation;
  for (Method m : shown.session->scene().methods)
    if (shown.session->scene().methods.size() >= 2) ui.compare_choice[static_cast<int>(m)] = true;
  shown.ui = std::move(ui);
}

// The keys of the help overlay, as actions.
void keyboard(Session& session, ui::UiState& ui, GLFWwindow* window) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const std::pair<int, ui::Action> keys[] = {
      {GLFW_KEY_SPACE, ui::Action::TogglePause}, {GLFW_KEY_S, ui::Action::Step},
      {GLFW_KEY_R, ui::Action::Reset},           {GLFW_KEY_C, ui::Action::ToggleCompare},
      {GLFW_KEY_H, ui::Action::TogglePanels},    {GLFW_KEY_F1, ui::Action::ToggleHelp},
      {GLFW_KEY_A, ui::Action::ToggleAccuracy},  {GLFW_KEY_G, ui::Action::ToggleRegion},
      {GLFW_KEY_M, ui::Action::ToggleMode},      {GLFW_KEY_P, ui::Action::TogglePresentation}};
  for (const auto& [key, action] : keys)
    if (ImGui::IsKeyPressed(key, false)) ui::perform(action, session, ui);
  for (int k = 0; k < 9; ++k)
    if (ImGui::IsKeyPressed(GLFW_KEY_1 + k, false))
      ui::perform(static_cast<ui::Action>(static_cast<int>(ui::Action::Method1) + k), session, ui);
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

// Reads the window's back buffer (what is about to be shown) into a PNG.
void screenshot(const std::string& path, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> flipped(image.rgba.size());
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.rgba.data() + y * row, flipped.data() + (height - 1 - y) * row, row);
  write_png(path, image, 6);
}

}  // namespace

int run_window(Prepared prepared, const WindowOptions& o) {
  std::optional<Script> script;
  if (o.script) script = load_script(*o.script, prepared.scene);

  glfwSetErrorCallback([](int, const char* message) { g_glfw_error = message; });
  if (!glfwInit())
    throw std::runtime_error(
        "the interactive app needs a display, and none could be opened (" + g_glfw_error +
        "). Run it on a desktop, under xvfb-run -a springlab view, or without one: springlab render SCENE --video out.mp4");
  struct Terminate {
    ~Terminate() { glfwTerminate(); }
  } terminate;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  const std::string title = "springlab - " + prepared.scene.name;
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  if (!window) throw std::runtime_error("no OpenGL 3.3 window could be made (" + g_glfw_error + ")");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(o.frames ? 0 : 1);

  float content_scale = 1.0f, unused = 1.0f;
  glfwGetWindowContentScale(window, &content_scale, &unused);
  const float scale = static_cast<float>(o.ui_scale) * std::max(1.0f, content_scale);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's folder
  io.LogFilename = nullptr;
  ui::apply_theme(scale);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int result = 0;
  {
    gfx::Renderer renderer;
    gfx::RenderTarget target;
    const std::string gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const bool software = gfx::software_renderer(gl_renderer);
    const int samples = o.msaa >= 0 ? o.msaa : software ? 0 : 4;
    // The software rasteriser draws with every core: the simulation takes one unless told.
    if (software && !o.threads_given) set_thread_count(1);

    Shown shown;
    const std::string first_name = prepared.scene.name;
    const bool background = !o.frames;
    show(shown, std::move(prepared), scale, first_name, background);
    if (!o.compare.empty()) shown.session->set_compare(o.compare);
    if (script) shown.session->play(*script);
    if (o.accuracy) {
      shown.ui.accuracy = true;
      shown.accuracy.start(*shown.session);
    }
    glfwSetWindowUserPointer(window, &shown);
    // A scene file dropped on the window opens.
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
      if (count > 0) static_cast<Shown*>(glfwGetWindowUserPointer(w))->dropped = paths[0];
    });

    std::optional<ui::Drag> drag;
    ui::FrameStats stats;
    std::deque<std::pair<Clock::time_point, double>> pace;  // (wall, simulated target) a frame
    int shown_w = 0, shown_h = 0;
    const double period = 1.0 / 60.0;
    auto next_frame = Clock::now();
    const auto start = Clock::now();
    long frames = 0;
    while (!glfwWindowShouldClose(window)) {
      if (!o.frames) {
        // Paced by the wall clock: one simulated frame every 1/60 s, whatever the display does.
        const double wait = std::chrono::duration<double>(next_frame - Clock::now()).count();
        if (wait > 0) glfwWaitEventsTimeout(wait);
        else glfwPollEvents();
        if (Clock::now() < next_frame) continue;
        next_frame = std::max(next_frame + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period)),
                              Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period)));
      } else {
        glfwPollEvents();
      }
      Session& session = *shown.session;
      ui::UiState& ui = shown.ui;

      int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
      glfwGetFramebufferSize(window, &fb_w, &fb_h);
      glfwGetWindowSize(window, &win_w, &win_h);
      if (fb_w <= 0 || fb_h <= 0) continue;  // minimised
      shown_w = fb_w;
      shown_h = fb_h;
      const double to_fb = static_cast<double>(fb_w) / std::max(1, win_w);

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();

      // The scene's part of the framebuffer (the panels' layout is in window units).
      draw::Viewport viewport = ui::scene_viewport(ui, win_w, win_h);
      viewport = {static_cast<int>(viewport.x * to_fb), static_cast<int>(viewport.y * to_fb),
                  static_cast<int>(viewport.width * to_fb), static_cast<int>(viewport.height * to_fb)};
      const draw::ViewCamera camera = draw::view_camera(ui.view.camera, viewport.width, viewport.height);

      // Mouse on the scene: left drags a particle, right orbits (pans in 2D), middle pans, wheel zooms.
      const ui::Pointer pointer{io.MousePos.x * to_fb, io.MousePos.y * to_fb};
      if (!io.WantCaptureMouse) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) drag = ui::press(session, camera, viewport, pointer, 14.0 * scale);
        const ImVec2 d = io.MouseDelta;
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
          if (ui.view.camera.view == View::Planar) ui::pan(ui.view.camera, camera, d.x * to_fb, d.y * to_fb);
          else ui::orbit(ui.view.camera, d.x, d.y);
        }
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f))
          ui::pan(ui.view.camera, camera, d.x * to_fb, d.y * to_fb);
        if (io.MouseWheel != 0.0f) ui::zoom(ui.view.camera, io.MouseWheel);
      }
      if (drag && ImGui::IsMouseDown(ImGuiMouseButton_Left)) ui::move(session, camera, viewport, pointer, *drag);
      if (drag && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        ui::release(session);
        drag.reset();
      }
      keyboard(session, ui, window);

      const ui::Requests requests = ui::draw_panels(session, ui, stats, win_w, win_h);
      shown.accuracy.open = ui.accuracy;
      ui::draw_compare_panel(shown.accuracy, session, scale, 380.0f * scale, 20.0f * scale, win_w - 400.0f * scale,
                             win_h * 0.62f);
      ui.accuracy = shown.accuracy.open;
      ui.view.line_scale = ui.presentation ? 1.6f : 1.0f;
      ui::OverlayOptions overlay;
      overlay.scale = scale * (ui.presentation ? ui::kPresentationScale : 1.0f);
      overlay.caption = !ui.panels;
      overlay.realtime = stats.realtime;
      ui::draw_overlay(session, camera,
                       {static_cast<int>(viewport.x / to_fb), static_cast<int>(viewport.y / to_fb),
                        static_cast<int>(viewport.width / to_fb), static_cast<int>(viewport.height / to_fb)},
                       ui.scene_name, overlay);
      std::optional<std::string> load = requests.load;
      if (shown.dropped) load = std::exchange(shown.dropped, std::nullopt);

      // Simulate this frame.
      const std::int64_t evals0 = session.primary().sim.counters().force_evals;
      const std::int64_t solves0 = session.primary().sim.counters().linear_solves;
      const std::int64_t iters0 = session.primary().sim.counters().solver_iterations;
      const auto sim_start = Clock::now();
      session.advance_frame();
      stats.sim_ms = std::chrono::duration<double, std::milli>(Clock::now() - sim_start).count();
      stats.force_evals = session.primary().sim.counters().force_evals - evals0;
      stats.linear_solves = session.primary().sim.counters().linear_solves - solves0;
      stats.solver_iterations = session.primary().sim.counters().solver_iterations - iters0;
      // The real-time factor over the last second: simulated time (what the lanes reached) against
      // the wall clock. Below 1 the simulation cannot keep up and the app slows down with it,
      // rather than drop simulated time; the panels say by how much.
      pace.emplace_back(Clock::now(), session.simulated_target());
      while (pace.size() > 2 && pace.front().first < pace.back().first - std::chrono::seconds(1)) pace.pop_front();
      if (pace.size() >= 2 && !session.paused()) {
        const double wall = std::chrono::duration<double>(pace.back().first - pace.front().first).count();
        const double simulated = (pace.back().second - pace.front().second) / std::max(1e-9, session.speed());
        if (wall > 0.25) {
          stats.realtime = simulated / wall;
          stats.fps = (pace.size() - 1) / wall;
        }
      }

      // Draw it, the panels over it, then show it.
      const auto draw_start = Clock::now();
      ImGui::Render();
      target.resize(fb_w, fb_h, samples);
      target.bind_for_drawing();
      renderer.draw(draw::build_frame(session, ui.view, viewport), fb_w, fb_h);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      target.resolve();
      target.blit_to_window(fb_w, fb_h);
      ++frames;
      if (o.frames && frames >= *o.frames) {
        if (o.screenshot) screenshot(*o.screenshot, fb_w, fb_h);
        glfwSwapBuffers(window);
        break;
      }
      glfwSwapBuffers(window);
      stats.draw_ms = std::chrono::duration<double, std::milli>(Clock::now() - draw_start).count();

      // A new scene, when asked: the current one keeps running if it does not load.
      if (load) {
        try {
          const std::string name = *load;
          Prepared next = prepare(name, {});
          shown.accuracy.sweep.cancel();
          show(shown, std::move(next), scale, name, background);
          glfwSetWindowTitle(window, ("springlab - " + shown.session->scene().name).c_str());
          drag.reset();
        } catch (const std::exception& e) {
          shown.ui.message = e.what();
        }
      }
    }

    if (o.frames) {
      // What happened, for whoever scripted the run (the tests read it).
      const double wall = std::chrono::duration<double>(Clock::now() - start).count();
      const Session& session = *shown.session;
      std::printf("frames     %ld in %.3g s: %.1f frames/s (%dx%d, %d samples, %s)\n", frames, wall, frames / wall,
                  shown_w, shown_h, samples, gl_renderer.c_str());
      for (const Lane& lane : session.lanes())
        std::printf("lane       %s at t = %.4g s%s\n", method_info(lane.sim.settings().method).name,
                    lane.sim.state().t, lane.sim.diverged() ? " (diverged)" : "");
      for (const Session::DragRecord& d : session.drags())
        std::printf("dragged    particle %d from (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g): %.4g m\n", d.particle,
                    d.from.x(), d.from.y(), d.from.z(), d.to.x(), d.to.y(), d.to.z(), (d.to - d.from).norm());
      if (o.screenshot) std::printf("screenshot %s\n", o.screenshot->c_str());
      for (const Lane& lane : session.lanes())
        if (lane.sim.diverged()) result = 3;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return result;
}

}  // namespace springlab::app
