// The app's panels, drawn with Dear ImGui: controls (scene, method, pause, step, reset, the
// stability gauge, k_s, k_d, dt, sub-steps (auto or fixed), mass, gravity, drag, friction,
// speed), the time of each lane and the real-time factor, compare mode, the view options, the
// stability region; the charts (energy, the watched particle's position with the exact solution,
// its phase plot); the divergence banner and the help overlay. The same panels are drawn in the
// window and, with `render --ui`, headlessly. They change the session only through its public
// functions.
//
// Layout (ui/layout.hpp, chosen by the screen): on a laptop or a monitor the left panel and the
// charts fit 1280x720 at scale 1 with nothing cut off (the rarer controls fold away); a small
// laptop, a tablet and a phone, upright or on its side, get their own; presentation mode (P) is for
// a projector: larger text, thicker lines, the left panel down to what a class watches, one chart.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "draw/scene_frame.hpp"
#include "session/session.hpp"
#include "springlab/lesson.hpp"
#include "ui/layout.hpp"
#include "ui/method_choice.hpp"

namespace springlab::ui {

// The cost of the last frame, measured by whoever runs the frame, and how fast simulated time
// goes against the wall clock over the last second (1 unless the simulation cannot keep up).
struct FrameStats {
  double sim_ms = 0.0, draw_ms = 0.0;
  std::int64_t force_evals = 0, linear_solves = 0, solver_iterations = 0;
  double realtime = 1.0;
  double fps = 0.0;  // frames shown a second of wall time (0: not measured, headless)
  // Whether the wall-clock times are shown: not in `render`'s frames, which must be the same
  // pixels for the same inputs (golden images): its work is shown instead.
  bool timed = true;
  // Each lane's work in the frame (the change of its counters); force_evals is their sum.
  std::vector<Counters> lanes;
};

// Every lane's counters now, and the frame's work since `before` (from lane_counters) into stats.
std::vector<Counters> lane_counters(const app::Session& session);
void count_frame(FrameStats& stats, const app::Session& session,
                 const std::vector<Counters>& before);

// Slider ranges, from the scene as loaded.
struct Ranges {
  double ks = 100, kd = 0, dt = 0.01, mass = 1, drag = 0, gravity = 0;
  static Ranges of(const app::Session& session);
};

struct UiState {
  float scale = 1.0f;
  bool panels = true;             // H hides them
  bool help = false;              // F1
  bool accuracy = false;          // the Compare panel (accuracy against cost), A
  bool presentation = false;      // P: for a projector
  bool region = false;            // G: the stability region
  bool tableau = false;           // Y: your method (a tableau typed in)
  bool sheet_open = false;        // Upright (ui/layout.hpp): the controls' sheet opened
  std::optional<bool> side_open;  // Side: the controls unfolded (unset: unless a lesson is taught)
  draw::ViewOptions view;
  Ranges ranges;
  std::vector<std::string> scenes;  // the picker's list
  std::string scene_name;
  char open_path[512] = "";
  int key_particle = 0;  // "A particle by keys": the one to hold
  std::string message;   // shown in a banner until dismissed (a file that failed to load)
  MethodChoice compare_choice;
  // A platform's own controls, drawn under the scene picker (the browser's Copy link, file
  // picker and UI scale); none on the desktop.
  std::function<void()> platform_controls;

  // Lessons: the picker's list ("hooke", "Hooke's spring and its exact motion"), the one being
  // taught (its name, or ""), the charts its step shows (filling the charts' panel),
  // and the height of the band across the top that holds its caption (window units; 0: none).
  std::vector<std::pair<std::string, std::string>> lessons;
  std::string lesson;
  std::vector<LessonChart> lesson_charts;
  float band = 0.0f;
};

struct Requests {
  std::optional<std::string> load;      // a scene name or file to open
  std::optional<std::string> lesson;    // a lesson to start ("" ends the one taught)
  std::optional<std::string> language;  // a language to speak from the next frame ("zh-CN", "en")
  bool quit = false;
};

Requests draw_panels(app::Session& session, UiState& ui, const FrameStats& stats, int width,
                     int height);

// The part of a width x height framebuffer the panels leave to the scene.
draw::Viewport scene_viewport(const UiState& ui, const app::Session& session, int width,
                              int height);

// Where the accuracy chart goes (ui/layout.hpp: place_accuracy); empty where it floats.
Rect accuracy_rect(const UiState& ui, const app::Session& session, int width, int height);

// The methods ticked for compare mode, in table order (at most four).
std::vector<Method> compare_methods(const UiState& ui);

// How much larger everything is in presentation mode.
inline constexpr float kPresentationScale = 1.4f;

}  // namespace springlab::ui
