// The interactive app, whatever shows it: one scene's session, the panels, the mouse on the scene
// (drag particles, orbit, pan, zoom), the keys, simulating a frame and drawing it with the shared
// renderer. A platform (app/window: a desktop GLFW window; app/web: the browser) makes the GL
// context, starts Dear ImGui's platform backend, runs the frame loop and shows the result; every
// frame it calls frame() between its backends' NewFrame and presenting the default framebuffer.
//
// Sections: pacing; the app.
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gfx/render_target.hpp"
#include "gfx/renderer.hpp"
#include "platform/app_settings.hpp"
#include "session/session.hpp"
#include "springlab/lesson.hpp"
#include "springlab/script.hpp"
#include "ui/compare_panel.hpp"
#include "ui/interaction.hpp"
#include "ui/keyboard_focus.hpp"
#include "ui/lesson_band.hpp"
#include "ui/panels.hpp"
#include "ui/tableau_panel.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

using Clock = std::chrono::steady_clock;

// One simulated frame every `period` of wall time, whatever the display's rate. A frame is due
// from `early` before its time (a browser's animation frames come with jitter; a window waits for
// the exact time instead); when the app falls behind, it catches up one frame, not all of them.
class FramePacer {
 public:
  explicit FramePacer(double period_s = 1.0 / 60.0, double early_s = 0.0);
  double seconds_to_next() const;  // <= 0: due
  bool take();                     // whether a frame is due now; if so, schedules the next

 private:
  Clock::duration period_, early_;
  Clock::time_point next_;
};

// The sizes of a frame: the framebuffer in pixels and the window in the units of mouse positions.
struct FrameSize {
  int fb_width = 0, fb_height = 0, win_width = 0, win_height = 0;
};

class InteractiveApp {
 public:
  // `samples`: multisampling of the scene; `background`: stability analyses beside the frame loop
  // (interactive), or made where needed (a scripted run: the same frames every time).
  InteractiveApp(Prepared first, const AppSettings& settings, std::optional<Script> script,
                 float scale, int samples, bool background);

  // One frame: the mouse and the keys, the panels, one simulated frame, the scene and the panels
  // drawn into the default framebuffer.
  void frame(const FrameSize& size);
  // The platform's own controls in the panels, under the scene picker (ui::UiState).
  void set_platform_controls(std::function<void()> draw) {
    ui_.platform_controls = std::move(draw);
  }

  // Opens a scene (a shipped name or a path) in place of the one shown, keeping the panels'
  // choices. When it cannot be opened, the scene shown goes on and the banner says why: false.
  bool open(const std::string& scene);
  // Opens it after the next frame (a file dropped on the window during one).
  void open_after_frame(std::string scene) { pending_ = std::move(scene); }
  // A change asked for from outside the panels (the browser's accessible controls, web/access.js):
  // made in the next frame where the panels make theirs, so that it interrupts a lesson as theirs
  // do.
  void control(std::function<void(Session&, ui::UiState&)> change) {
    controls_.push_back(std::move(change));
  }
  // A one-line message in the panels' banner (a bad file, a bad link).
  void say(std::string message) { ui_.message = std::move(message); }

  // A new scale for the panels and text; the platform then rebuilds its font texture.
  void set_scale(float scale);
  // The language asked for in the last frame's panels, made current (util/language.hpp) with the
  // fonts it needs; the platform calls this between frames and, when true, rebuilds its font
  // texture. A language that cannot be spoken (its catalog or font missing) leaves the one in use
  // and the banner says why.
  bool apply_language();
  // The language of the URL or the command line, set before the first frame: true if it changed.
  bool set_language(const std::string& tag);
  float scale() const { return ui_.scale; }

  Session& session() { return *session_; }
  const Session& session() const { return *session_; }
  const ui::UiState& ui() const { return ui_; }
  const std::string& scene_name() const { return ui_.scene_name; }
  bool quit_requested() const { return quit_; }  // Escape, or the panels' Quit
  // The scene opened by the last frame, if any (the window puts its name in the title).
  std::optional<std::string> take_opened() { return std::exchange(opened_, std::nullopt); }
  const ui::FrameStats& stats() const { return stats_; }
  const ui::ComparePanel& accuracy() const {
    return accuracy_;
  }  // the accuracy-against-cost panel (A)

  // Lessons. start_lesson opens a lesson at a step (from 0); lesson_step moves to another of its
  // steps (a new session from the step's start, its script playing); a drag or a change made by
  // the class interrupts the lesson (its script stops) until resume_lesson replays the step.
  // Keys: right / page down / N the next step, left / page up / B the one before (presenters'
  // clickers send page up and down).
  void start_lesson(Lesson lesson, int step = 0);
  void lesson_step(int step);
  void next_step();
  void previous_step();
  void resume_lesson() { lesson_step(step_); }
  void end_lesson();
  const std::optional<Lesson>& lesson() const { return lesson_; }
  int step() const { return step_; }
  bool interrupted() const { return interrupted_; }

 private:
  void show(Prepared prepared, const std::string& name);
  void mouse(const std::vector<draw::LaneView>& views, double to_fb);
  void keyboard();
  void simulate();
  ui::LessonBand band() const;

  std::unique_ptr<Session> session_;
  ui::UiState ui_;
  ui::ComparePanel accuracy_;
  ui::TableauPanel tableau_;
  std::vector<std::string> tableaux_ = shipped_tableaux();  // its menu
  gfx::Renderer renderer_;
  gfx::RenderTarget target_;
  int samples_;
  bool background_;
  std::optional<ui::Drag> drag_;
  ui::KeyboardFocus keys_;  // whose the keys are: the scene's or the panels'
  ui::FrameStats stats_;
  std::deque<std::pair<Clock::time_point, double>> pace_;  // (wall, simulated target) a frame
  std::optional<std::string> pending_, opened_, language_;
  std::optional<Lesson> lesson_;
  int step_ = 0, lesson_number_ = 0;  // lesson_number_: its place in the course (0: not shipped)
  bool interrupted_ = false;
  std::optional<std::function<void()>> lesson_move_;  // a move between steps, made after the frame
  std::vector<std::function<void(Session&, ui::UiState&)>>
      controls_;  // control()'s, for the next frame
  bool quit_ = false;
};

}  // namespace springlab::app
