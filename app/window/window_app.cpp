#include "window/window_app.hpp"

#include "homework/homework_watch.hpp"
#include "springlab/text.hpp"
#include "ui/homework_status.hpp"
#include "util/language.hpp"

// GL through epoxy first, then GLFW without its own GL header.
#include "gfx/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "gfx/headless_context.hpp"
#include "io/png.hpp"
#include "platform/interactive_app.hpp"
#include "springlab/error.hpp"
#include "ui/theme.hpp"
#include "window/key_presses.hpp"

namespace springlab::app {

namespace {

std::string g_glfw_error;

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

// The window and its OpenGL 3.3 core context, current; swapping unpaced for a --frames run.
GLFWwindow* open_window(const WindowOptions& o, const std::string& title) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  if (!window)
    throw std::runtime_error("no OpenGL 3.3 window could be made (" + g_glfw_error + ")");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(o.frames ? 0 : 1);
  return window;
}

// A --frames run's clock: frames drawn, wall seconds in all and since the first frame (the
// scene's analysis), and the simulated time then.
struct RunTimes {
  long frames;
  double wall, steady, first_t;
};

// What a --frames run did, for whoever scripted it (the tests read it); its exit status (3 when a
// lane diverged or went unstable).
int report_run(const Session& session, const WindowOptions& o, const RunTimes& r, int width,
               int height, int samples, const std::string& renderer) {
  std::printf("frames     %ld in %.3g s: %.1f frames/s (%dx%d, %d samples, %s)\n", r.frames, r.wall,
              r.frames / r.wall, width, height, samples, renderer.c_str());
  // Each frame advances 1/60 s here, as fast as it can: the real-time factor is what the window
  // would show (above 1, it waits for the display instead).
  if (r.frames > 1 && r.steady > 0.0)
    std::printf("steady     %.1f frames/s, %.3gx real time (after the first frame)\n",
                (r.frames - 1) / r.steady,
                (session.primary().sim.state().t - r.first_t) / r.steady);
  for (const Lane& lane : session.lanes())
    std::printf("lane       %s at t = %.4g s%s\n", lane_name(lane).c_str(), lane.sim.state().t,
                lane.sim.diverged() ? (" (diverged: " + lane.sim.divergence()->reason + ")").c_str()
                : lane.sim.instability() ? " (unstable)"
                                         : "");
  for (const Session::DragRecord& d : session.drags())
    std::printf("dragged    particle %d from (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g): %.4g m\n",
                d.particle, d.from.x(), d.from.y(), d.from.z(), d.to.x(), d.to.y(), d.to.z(),
                (d.to - d.from).norm());
  if (o.screenshot) std::printf("screenshot %s\n", o.screenshot->c_str());
  std::printf("language   %s\n", current_language().c_str());
  int result = 0;
  for (const Lane& lane : session.lanes())
    if (lane.sim.trouble()) result = 3;
  return result;
}

// Dear ImGui for the window: no files of its own, the language, the theme at `scale`.
void start_imgui(GLFWwindow* window, const AppSettings& settings, float scale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's folder
  io.LogFilename = nullptr;
  // The language before the fonts (they carry its glyphs): --lang, or the environment's, which
  // falls back to English where it cannot be spoken.
  if (!settings.language.empty()) {
    use_language(settings.language);
  } else {
    try {
      use_language(environment_language());
    } catch (const InputError& e) {
      std::fprintf(stderr, "springlab: %s; speaking English\n", e.what());
    }
  }
  ui::apply_theme(scale);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

// The frames until the window closes (or --frames are drawn): paced by the wall clock, one
// simulated frame every 1/60 s, or as fast as they come with --frames. `shown_w` x `shown_h`:
// the last frame's size.
RunTimes frame_loop(GLFWwindow* window, InteractiveApp& app, const WindowOptions& o,
                    const std::vector<KeyPress>& keys, HomeworkWatch* homework, int& shown_w,
                    int& shown_h) {
  FramePacer pacer;
  const auto start = Clock::now();
  long frames = 0;
  auto first_frame = start;
  double first_t = 0.0;
  while (!glfwWindowShouldClose(window)) {
    if (!o.frames) {
      // Paced by the wall clock: one simulated frame every 1/60 s, whatever the display does.
      const double wait = pacer.seconds_to_next();
      if (wait > 0)
        glfwWaitEventsTimeout(wait);
      else
        glfwPollEvents();
      if (!pacer.take()) continue;
    } else {
      glfwPollEvents();
    }

    FrameSize size;
    glfwGetFramebufferSize(window, &size.fb_width, &size.fb_height);
    glfwGetWindowSize(window, &size.win_width, &size.win_height);
    if (size.fb_width <= 0 || size.fb_height <= 0) continue;  // minimised
    shown_w = size.fb_width;
    shown_h = size.fb_height;

    if (app.apply_language()) ImGui_ImplOpenGL3_DestroyDeviceObjects();  // its font texture, remade
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    press_keys(keys, frames, 2);  // (from the second frame: the first analyses the scene)
    if (homework) homework->poll(app.session());
    app.frame(size);
    if (app.quit_requested()) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (const auto opened = app.take_opened())
      glfwSetWindowTitle(window, ("springlab - " + app.session().scene().name).c_str());
    ++frames;
    if (frames == 1) {  // the steady figures start after the first frame (the scene's analysis)
      first_frame = Clock::now();
      first_t = app.session().primary().sim.state().t;
    }
    if (o.frames && frames >= *o.frames) {
      if (o.screenshot) screenshot(*o.screenshot, size.fb_width, size.fb_height);
      glfwSwapBuffers(window);
      break;
    }
    glfwSwapBuffers(window);
  }

  return {frames, std::chrono::duration<double>(Clock::now() - start).count(),
          std::chrono::duration<double>(Clock::now() - first_frame).count(), first_t};
}

}  // namespace

int run_window(const AppSettings& settings, const WindowOptions& o) {
  Prepared prepared = prepare(settings.scene, settings.sim);
  if (settings.compare)
    make_scene_kind(prepared.scene)
        ->lanes_named(*settings.compare, "--compare");  // before any window
  std::optional<Script> script;
  if (settings.script) script = load_script(*settings.script, prepared.scene);
  // The student's rope, built and checked before any window opens: a file that does not compile
  // is bad input, display or not.
  std::unique_ptr<HomeworkWatch> homework;
  if (o.homework) homework = std::make_unique<HomeworkWatch>(*o.homework);
  const std::vector<KeyPress> keys =
      o.keys ? parse_key_presses(*o.keys, "--keys") : std::vector<KeyPress>{};

  glfwSetErrorCallback([](int, const char* message) { g_glfw_error = message; });
  if (!glfwInit())
    throw std::runtime_error("the interactive app needs a display, and none could be opened (" +
                             g_glfw_error +
                             "). Run it on a desktop, under xvfb-run -a springlab view, or without "
                             "one: springlab render SCENE --video out.mp4");
  struct Terminate {
    ~Terminate() { glfwTerminate(); }
  } terminate;
  GLFWwindow* window = open_window(o, "springlab - " + prepared.scene.name);

  float content_scale = 1.0f, unused = 1.0f;
  glfwGetWindowContentScale(window, &content_scale, &unused);
  const float scale = static_cast<float>(settings.ui_scale) * std::max(1.0f, content_scale);

  start_imgui(window, settings, scale);

  int result = 0;
  {
    const std::string gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const bool software = gfx::software_renderer(gl_renderer);
    const int samples = o.msaa >= 0 ? o.msaa : software ? 0 : 4;
    // The software rasteriser draws with every core: the simulation takes one unless told.
    if (software && !o.threads_given) set_thread_count(1);

    InteractiveApp app(std::move(prepared), settings, std::move(script), scale, samples, !o.frames);
    if (homework)
      app.set_platform_controls([&homework] { ui::draw_homework_status(homework->status()); });
    glfwSetWindowUserPointer(window, &app);
    // A scene file dropped on the window opens.
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
      if (count > 0)
        static_cast<InteractiveApp*>(glfwGetWindowUserPointer(w))->open_after_frame(paths[0]);
    });

    int shown_w = 0, shown_h = 0;
    const RunTimes times = frame_loop(window, app, o, keys, homework.get(), shown_w, shown_h);
    if (o.frames)
      result = report_run(app.session(), o, times, shown_w, shown_h, samples, gl_renderer);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return result;
}

}  // namespace springlab::app
