#include "platform/interactive_app.hpp"

#include "springlab/text.hpp"
#include "util/language.hpp"

// GL first (epoxy or ES 3), then GLFW without its own GL header: its key codes are the ones
// Dear ImGui's GLFW backend reports, on the desktop and in the browser alike.
#include "gfx/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <vector>

#include "draw/scene_frame.hpp"
#include "lesson/lesson_library.hpp"
#include "springlab/error.hpp"
#include "ui/actions.hpp"
#include "ui/overlay.hpp"
#include "ui/theme.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

// --- Pacing --------------------------------------------------------------------------------

namespace {
Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}
}  // namespace

FramePacer::FramePacer(double period_s, double early_s)
    : period_(seconds(period_s)), early_(seconds(early_s)), next_(Clock::now()) {}

double FramePacer::seconds_to_next() const {
  return std::chrono::duration<double>(next_ - early_ - Clock::now()).count();
}

bool FramePacer::take() {
  const auto now = Clock::now();
  if (now < next_ - early_) return false;
  next_ = std::max(next_ + period_, now - period_);
  return true;
}

// --- The app -------------------------------------------------------------------------------

InteractiveApp::InteractiveApp(Prepared first, const AppSettings& settings,
                               std::optional<Script> script, float scale, int samples,
                               bool background)
    : samples_(samples), background_(background) {
  ui_.scale = scale;
  for (const std::string& file : shipped_lesson_files()) {
    try {
      Lesson lesson = open_lesson(file);
      ui_.lessons.emplace_back(lesson.name, lesson.title);
    } catch (const std::exception&) {
      // (a shipped lesson that does not load is left out of the menu; the tests load them all)
    }
  }
  const std::string name = first.scene.name;
  show(std::move(first), name);
  if (settings.compare)
    session_->set_compare_rows(session_->kind().lanes_named(*settings.compare, "--compare"));
  ui_.view.compare_layout = settings.compare_layout;
  if (script) session_->play(std::move(*script));
  if (settings.accuracy) {
    ui_.accuracy = true;
    accuracy_.start(*session_);
  }
  if (settings.region) ui_.region = true;
  if (settings.lesson) {
    Lesson lesson = open_lesson(*settings.lesson);
    check_lesson_step(lesson, settings.lesson_step, "--step");
    start_lesson(std::move(lesson), settings.lesson_step - 1);
  }
}

// --- Lessons -------------------------------------------------------------------------------

void InteractiveApp::start_lesson(Lesson lesson, int step) {
  const int steps = static_cast<int>(lesson.steps.size());
  lesson_ = std::move(lesson);
  ui_.lesson = lesson_->name;
  lesson_number_ = course_number(*lesson_);
  lesson_step(std::clamp(step, 0, steps - 1));
}

void InteractiveApp::lesson_step(int k) {
  if (!lesson_) return;
  const LessonStep& step = lesson_->steps[k];
  StepSetup setup;
  try {
    setup = setup_step(step);
  } catch (const std::exception& e) {
    ui_.message = e.what();  // (a lesson file changed on disc since it was opened)
    return;
  }
  accuracy_.sweep.cancel();
  show(std::move(setup.prepared), step.scene);
  begin_step(*session_, step, setup);
  drag_.reset();
  step_ = k;
  interrupted_ = false;
  ui::show_step(ui_, accuracy_, *lesson_, k);
  if (step.accuracy) accuracy_.start(*session_);
}

void InteractiveApp::next_step() {
  if (!lesson_) return;
  if (step_ + 1 < static_cast<int>(lesson_->steps.size())) return lesson_step(step_ + 1);
  // After the last step: the next lesson of the course, if there is one.
  const std::vector<std::string> files = shipped_lesson_files();
  if (lesson_number_ > 0 && lesson_number_ < static_cast<int>(files.size())) {
    try {
      return start_lesson(open_lesson(files[lesson_number_]));
    } catch (const std::exception& e) {
      ui_.message = e.what();
      return;
    }
  }
  end_lesson();
}

void InteractiveApp::previous_step() {
  if (lesson_ && step_ > 0) lesson_step(step_ - 1);
}

void InteractiveApp::end_lesson() {
  lesson_.reset();
  interrupted_ = false;
  ui_.lesson.clear();
  ui_.band = 0.0f;
  ui_.lesson_charts.clear();
  session_->stop_script();
}

ui::LessonBand InteractiveApp::band() const {
  ui::LessonBand b =
      ui::band_of(*lesson_, step_, lesson_number_, static_cast<int>(ui_.lessons.size()));
  b.elapsed =
      session_->simulated_target() / lesson_->steps[step_].speed;  // (stands still while paused)
  b.interrupted = interrupted_;
  return b;
}

void InteractiveApp::show(Prepared p, const std::string& name) {
  const auto compare = ui_.compare_choice;
  const auto layout = ui_.view.compare_layout;  // (the class's choice, kept from scene to scene)
  const bool presentation = ui_.presentation;
  const float scale = ui_.scale;
  session_ = std::make_unique<Session>(std::move(p.scene), p.settings, 60.0);
  // Interactive: stability analyses on a worker thread, the frame loop never waiting for one.
  // Scripted (--frames): made where needed, so that the same run gives the same frames.
  session_->set_background_analysis(background_);
  ui::UiState ui;
  ui.scale = scale;
  ui.view = draw::ViewOptions::for_scene(session_->scene());
  ui.view.compare_layout = layout;
  ui.ranges = ui::Ranges::of(*session_);
  ui.scenes = shipped_scenes();
  ui.scene_name = name;
  ui.compare_choice = compare;
  ui.presentation = presentation;
  ui.platform_controls = std::move(ui_.platform_controls);
  ui.lessons = std::move(ui_.lessons);
  ui.lesson = ui_.lesson;
  ui.band = ui_.band;
  ui.lesson_charts = ui_.lesson_charts;
  for (Method m : session_->scene().methods)
    if (session_->scene().methods.size() >= 2) ui.compare_choice.set(m, true);
  ui_ = std::move(ui);
}

bool InteractiveApp::open(const std::string& scene) {
  try {
    Prepared next = prepare(scene, {});
    accuracy_.sweep.cancel();
    show(std::move(next), scene);
    drag_.reset();
    opened_ = scene;
    return true;
  } catch (const std::exception& e) {
    ui_.message = e.what();
    return false;
  }
}

bool InteractiveApp::apply_language() {
  const std::optional<std::string> tag = std::exchange(language_, std::nullopt);
  return tag && set_language(*tag);
}

bool InteractiveApp::set_language(const std::string& tag) {
  const std::string before = current_language();
  try {
    use_language(tag);
  } catch (const std::exception& e) {
    ui_.message = e.what();
    return false;
  }
  if (current_language() == before) return false;
  set_scale(ui_.scale);  // the fonts again, with the glyphs of the language now spoken
  return true;
}

void InteractiveApp::set_scale(float scale) {
  ui_.scale = scale;
  if (lesson_) ui_.band = ui::lesson_band_height(scale);
  ImGui::GetStyle() = ImGuiStyle();  // apply_theme scales the sizes it is given
  ui::apply_theme(scale);
}

// Mouse on the scene: left drags a particle, right orbits (pans in 2D), middle pans, wheel zooms.
void InteractiveApp::mouse(const std::vector<draw::LaneView>& views, double to_fb) {
  const ImGuiIO& io = ImGui::GetIO();
  Session& session = *session_;
  const ui::Pointer pointer{io.MousePos.x * to_fb, io.MousePos.y * to_fb};
  // The view under the pointer (apart, a lane's own), or the one a drag started in.
  const draw::LaneView* under = draw::view_at(views, pointer.x, pointer.y);
  if (!under) under = &views.front();  // (the camera moves on past the scene's edge)
  if (!io.WantCaptureMouse) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !under->lanes.empty())
      drag_ = ui::press(session, under->view, under->viewport, pointer, 14.0 * ui_.scale,
                        under->lanes.front());
    const ImVec2 d = io.MouseDelta;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
      if (ui_.view.camera.view == View::Planar)
        ui::pan(ui_.view.camera, under->view, d.x * to_fb, d.y * to_fb);
      else
        ui::orbit(ui_.view.camera, d.x, d.y);
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f))
      ui::pan(ui_.view.camera, under->view, d.x * to_fb, d.y * to_fb);
    if (io.MouseWheel != 0.0f) ui::zoom(ui_.view.camera, io.MouseWheel);
  }
  const draw::LaneView* held = drag_ ? draw::view_of(views, drag_->lane) : nullptr;
  if (drag_ && held && ImGui::IsMouseDown(ImGuiMouseButton_Left))
    ui::move(session, held->view, held->viewport, pointer, *drag_);
  if (drag_ && (!held || !ImGui::IsMouseDown(ImGuiMouseButton_Left))) {
    ui::release(session);
    drag_.reset();
  }
}

// The keys of the help overlay, as actions. While the panels have the keyboard (F6: ui/
// keyboard_focus.hpp), Space, Esc and the arrows are theirs.
void InteractiveApp::keyboard() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool panels = ui::update_keyboard_focus(keys_);
  if (io.WantTextInput) return;
  if (!panels && ImGui::IsKeyPressed(GLFW_KEY_SPACE, false))
    ui::perform(ui::Action::TogglePause, *session_, ui_);
  const std::pair<int, ui::Action> keys[] = {{GLFW_KEY_S, ui::Action::Step},
                                             {GLFW_KEY_R, ui::Action::Reset},
                                             {GLFW_KEY_C, ui::Action::ToggleCompare},
                                             {GLFW_KEY_H, ui::Action::TogglePanels},
                                             {GLFW_KEY_F1, ui::Action::ToggleHelp},
                                             {GLFW_KEY_A, ui::Action::ToggleAccuracy},
                                             {GLFW_KEY_G, ui::Action::ToggleRegion},
                                             {GLFW_KEY_M, ui::Action::ToggleMode},
                                             {GLFW_KEY_P, ui::Action::TogglePresentation},
                                             {GLFW_KEY_Y, ui::Action::ToggleTableau}};
  for (const auto& [key, action] : keys)
    if (ImGui::IsKeyPressed(key, false)) ui::perform(action, *session_, ui_);
  // Keys 1 to 9: the table's first nine rows.
  for (int k = 0; k < std::min<int>(9, static_cast<int>(methods().size())); ++k)
    if (ImGui::IsKeyPressed(GLFW_KEY_1 + k, false))
      ui::perform(static_cast<ui::Action>(static_cast<int>(ui::Action::Method1) + k), *session_,
                  ui_);
  if (panels) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) quit_ = true;
  if (lesson_) {
    for (int key : {GLFW_KEY_RIGHT, GLFW_KEY_PAGE_DOWN, GLFW_KEY_N})
      if (ImGui::IsKeyPressed(key, false)) lesson_move_ = [this] { next_step(); };
    for (int key : {GLFW_KEY_LEFT, GLFW_KEY_PAGE_UP, GLFW_KEY_B})
      if (ImGui::IsKeyPressed(key, false)) lesson_move_ = [this] { previous_step(); };
  }
}

void InteractiveApp::simulate() {
  Session& session = *session_;
  const std::vector<Counters> before = ui::lane_counters(session);
  const auto sim_start = Clock::now();
  session.advance_frame();
  stats_.sim_ms = std::chrono::duration<double, std::milli>(Clock::now() - sim_start).count();
  ui::count_frame(stats_, session, before);
  // The real-time factor over the last second: simulated time (what the lanes reached) against
  // the wall clock. Below 1 the simulation cannot keep up and the app slows down with it,
  // rather than drop simulated time; the panels say by how much.
  pace_.emplace_back(Clock::now(), session.simulated_target());
  while (pace_.size() > 2 && pace_.front().first < pace_.back().first - std::chrono::seconds(1))
    pace_.pop_front();
  if (pace_.size() >= 2 && !session.paused()) {
    const double wall =
        std::chrono::duration<double>(pace_.back().first - pace_.front().first).count();
    const double simulated =
        (pace_.back().second - pace_.front().second) / std::max(1e-9, session.speed());
    if (wall > 0.25) {
      stats_.realtime = simulated / wall;
      stats_.fps = (pace_.size() - 1) / wall;
    }
  }
}

namespace {

// The accuracy chart (ui/compare_panel.hpp), open while ui.accuracy is, where the layout puts it
// (in a lesson or beside compare mode's lanes: the scene's and the charts' place); then the
// tableau panel, open while ui.tableau is. Each panel's open flag goes back to `ui` as its window
// left it.
void draw_app_charts(ui::UiState& ui, ui::ComparePanel& accuracy, ui::TableauPanel& tableau,
                     const std::vector<std::string>& tableaux, Session& session, float scale,
                     int win_w, int win_h) {
  accuracy.open = ui.accuracy;
  accuracy.sweep.advance();  // (without threads: the sweep's next pieces; else nothing)
  ui::draw_compare_panel(accuracy, session, scale, ui::accuracy_rect(ui, session, win_w, win_h),
                         win_w, win_h);
  ui.accuracy = accuracy.open;
  tableau.open = ui.tableau;
  ui::draw_tableau_panel(tableau, session, tableaux, scale);
  ui.tableau = tableau.open;
}

// The overlay (ui/overlay.hpp) over the scene: its viewport, given in framebuffer pixels, drawn in
// window units (to_fb framebuffer pixels a unit); the caption where the panels are hidden, and
// larger in presentation.
void draw_app_overlay(const Session& session, const ui::UiState& ui, const ui::FrameStats& stats,
                      float scale, const draw::Viewport& viewport, double to_fb) {
  ui::OverlayOptions overlay;
  overlay.scale = scale * (ui.presentation ? ui::kPresentationScale : 1.0f);
  overlay.caption = !ui.panels;
  overlay.realtime = stats.realtime;
  overlay.trails = ui.view.trails;
  const draw::Viewport in_window{
      static_cast<int>(viewport.x / to_fb), static_cast<int>(viewport.y / to_fb),
      static_cast<int>(viewport.width / to_fb), static_cast<int>(viewport.height / to_fb)};
  ui::draw_overlay(session,
                   draw::lane_views(session, ui.view.camera, ui.view.compare_layout, in_window),
                   in_window, ui.scene_name, overlay);
}

}  // namespace

void InteractiveApp::frame(const FrameSize& size) {
  ImGui::NewFrame();
  const int win_w = size.win_width, win_h = size.win_height;
  const double to_fb = static_cast<double>(size.fb_width) / std::max(1, win_w);
  // The lesson's band as tall as its caption needs at this width.
  if (lesson_) ui_.band = ui::lesson_band_height(band(), static_cast<float>(win_w), ui_.scale);

  // The scene's part of the framebuffer (the panels' layout is in window units).
  draw::Viewport viewport = ui::scene_viewport(ui_, *session_, win_w, win_h);
  viewport = {static_cast<int>(viewport.x * to_fb), static_cast<int>(viewport.y * to_fb),
              static_cast<int>(viewport.width * to_fb), static_cast<int>(viewport.height * to_fb)};
  // What the class changes (a drag, a slider, a key) interrupts a lesson: compared around the
  // input.
  const std::uint64_t edits = session_->edits();
  for (auto& change : std::exchange(controls_, {})) change(*session_, ui_);
  // The views of the lanes (apart in compare: a view each), in framebuffer units.
  const std::vector<draw::LaneView> views =
      draw::lane_views(*session_, ui_.view.camera, ui_.view.compare_layout, viewport,
                       static_cast<float>(2.0 * to_fb));
  mouse(views, to_fb);
  keyboard();

  Session& session = *session_;
  const ui::Requests requests = ui::draw_panels(session, ui_, stats_, win_w, win_h);
  const float scale = ui_.scale;
  if (lesson_) {
    const ui::BandRequests asked = ui::draw_lesson_band(band(), static_cast<float>(win_w), scale);
    if (asked.back) lesson_move_ = [this] { previous_step(); };
    if (asked.next) lesson_move_ = [this] { next_step(); };
    if (asked.resume) lesson_move_ = [this] { resume_lesson(); };
    if (asked.end) lesson_move_ = [this] { end_lesson(); };
  }
  if (requests.lesson) {
    const std::string name = *requests.lesson;
    lesson_move_ = [this, name] {
      if (name.empty()) return end_lesson();
      try {
        start_lesson(open_lesson(name));
      } catch (const std::exception& e) {
        ui_.message = e.what();
      }
    };
  }
  draw_app_charts(ui_, accuracy_, tableau_, tableaux_, session, scale, win_w, win_h);
  ui_.view.line_scale = ui_.presentation ? 1.6f : 1.0f;
  draw_app_overlay(session, ui_, stats_, scale, viewport, to_fb);
  if (requests.quit) quit_ = true;
  if (requests.language) language_ = requests.language;
  std::optional<std::string> load = requests.load;
  if (pending_) load = std::exchange(pending_, std::nullopt);
  if (lesson_ && !interrupted_ && (session.edits() != edits || load)) {
    interrupted_ = true;
    session.stop_script();
  }

  ui::end_keyboard_focus_frame(keys_);
  simulate();

  // Draw it, the panels over it, into the default framebuffer.
  const auto draw_start = Clock::now();
  ImGui::Render();
  target_.resize(size.fb_width, size.fb_height, samples_);
  target_.bind_for_drawing();
  renderer_.draw(draw::build_frames(session, ui_.view, viewport), size.fb_width, size.fb_height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  target_.resolve();
  target_.blit_to_window(size.fb_width, size.fb_height);
  stats_.draw_ms = std::chrono::duration<double, std::milli>(Clock::now() - draw_start).count();

  // A new scene, when asked: the current one keeps running if it does not load. A move in a
  // lesson, when asked.
  if (load) open(*load);
  if (lesson_move_) std::exchange(lesson_move_, std::nullopt).value()();
}

}  // namespace springlab::app
