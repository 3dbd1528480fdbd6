// springlab render SCENE | --lesson NAME --out DIR | --video FILE.mp4: headless frames or video
// (no display, no GPU needed). Frame k shows the scene at presentation time k / fps (session.hpp);
// a lesson's steps follow one another, each for its duration, under the lesson's band. The output
// appears only when complete.
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "draw/scene_frame.hpp"
#include "gfx/offscreen.hpp"
#include "io/frame_writer.hpp"
#include "lesson/lesson_library.hpp"
#include "springlab/error.hpp"
#include "springlab/script.hpp"
#include "ui/compare_panel.hpp"
#include "ui/lesson_band.hpp"
#include "ui/overlay.hpp"
#include "ui/panels.hpp"
#include "ui/text_fit.hpp"
#include "util/data_dir.hpp"
#include "util/language.hpp"
#include "util/progress.hpp"

namespace springlab::app {

namespace {

struct RenderOptions {
  std::string scene;
  SimOptions sim;
  std::optional<std::string> out, video, script, size = "1280x720", compare, compare_layout, select,
                                                 lesson;
  std::optional<std::int64_t> frames;
  std::optional<double> duration;
  double fps = 60.0;
  bool ui = false, software = false, check_text = false;
  std::optional<double> ui_scale;  // default: the frame's height / 720, at least 0.6
  std::string lang =
      "en";  // the panels' and captions' language (not the environment's: frames repeat)
};

void parse_size(const std::string& text, int& width, int& height) {
  char x = 0;
  std::istringstream s(text);
  if (!(s >> width >> x >> height) || x != 'x' || !s.eof() || width < 16 || height < 16 ||
      width > 7680 || height > 4320)
    throw InputError(
        "--size: must be WIDTHxHEIGHT, each from 16 to 7680 x 4320, for example 1280x720; got '" +
        text + "'");
}

// A folder made for the output, removed again if the render fails before putting anything in it.
struct MadeFolder {
  std::filesystem::path path;
  bool made = false;
  ~MadeFolder() {
    std::error_code ec;
    if (made && std::filesystem::is_empty(path, ec)) std::filesystem::remove(path, ec);
  }
};

// One continuous piece of a render: a session with what is drawn over it. A scene is one shot;
// a lesson is one a step, each from its step's start, with the lesson's band across the top.
struct Shot {
  std::unique_ptr<Session> session;
  ui::UiState ui;
  std::unique_ptr<ui::ComparePanel> accuracy;  // a lesson step that shows the accuracy chart
  std::optional<ui::LessonBand> band;
  std::int64_t frames = 0;
};

// The UI state a shot starts with.
ui::UiState shot_ui(const Session& session, const std::string& scene_name, float scale) {
  ui::UiState ui;
  ui.scale = scale;
  ui.view = draw::ViewOptions::for_scene(session.scene());
  ui.ranges = ui::Ranges::of(session);
  ui.scene_name = scene_name;
  ui.scenes = shipped_scenes();
  // The lessons' picker, as the app has it (its titles from the lesson files).
  for (const std::string& file : shipped_lesson_files()) {
    const Lesson lesson = open_lesson(file);
    ui.lessons.emplace_back(lesson.name, lesson.title);
  }
  return ui;
}

// Step k of a lesson as a shot: its session, its chart, region and mode, its band; the accuracy
// sweep, if it shows one, run to the end first (the frames do not depend on how fast it runs).
Shot lesson_shot(const Lesson& lesson, int k, int number, int count, double fps, float scale) {
  const LessonStep& step = lesson.steps[k];
  Shot shot;
  shot.session = step_session(step, fps, false);
  shot.ui = shot_ui(*shot.session, shot.session->scene().name, scale);
  auto accuracy = std::make_unique<ui::ComparePanel>();
  ui::show_step(shot.ui, *accuracy, lesson, k);
  if (step.accuracy) {
    accuracy->start(*shot.session);
    accuracy->sweep.wait();
    shot.accuracy = std::move(accuracy);
  }
  shot.band = ui::band_of(lesson, k, number, count);
  shot.band->interactive = false;
  shot.frames = std::max<std::int64_t>(1, std::llround(step.duration * fps));
  return shot;
}

// Why a lesson is recorded with its own values, and how to record each of its steps with the
// class's: a lesson's captions state its values ("Euler is stable while h <= k_d / k_s = 0.02 s")
// and `lesson check` measures its claims at them, so other values would make it say what is false.
std::string lesson_takes_its_values(const RenderOptions& o) {
  const Lesson lesson = open_lesson(*o.lesson);
  std::string s =
      "render --lesson: a lesson is recorded with its own values: its captions state them (each "
      "step sets its "
      "scene, methods, k_s, k_d and dt) and `springlab lesson check` measures its claims there, so "
      "--script, --compare, --method, --dt, --substeps, --ks, --kd and --set do not go with it. To "
      "record a "
      "step with the class's values, render its scene with them:";
  const auto number = [](double v) {
    char t[32];
    std::snprintf(t, sizeof t, "%.6g", v);
    return std::string(t);
  };
  for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
    const LessonStep& step = lesson.steps[k];
    std::string c = "springlab render " + step.scene;
    for (const std::string& set : step.sets) c += " --set " + set;
    for (const std::string& set : o.sim.sets) c += " --set " + set;
    std::string lanes;
    for (const std::string& lane : step.compare) lanes += (lanes.empty() ? "" : ",") + lane;
    if (o.compare) lanes = *o.compare;
    if (!lanes.empty())
      c += " --compare " + lanes;
    else if (o.sim.method)
      c += " --method " + *o.sim.method;
    else if (step.method)
      c += std::string(" --method ") + method_info(*step.method).name;
    if (o.sim.dt || step.dt) c += " --dt " + number(o.sim.dt ? *o.sim.dt : *step.dt);
    if (o.sim.substeps)
      c += " --substeps " + *o.sim.substeps;
    else if (step.substeps)
      c += " --substeps " +
           (*step.substeps == 0 ? std::string("auto") : std::to_string(*step.substeps));
    if (o.sim.ks || step.ks) c += " --ks " + number(o.sim.ks ? *o.sim.ks : *step.ks);
    if (o.sim.kd || step.kd) c += " --kd " + number(o.sim.kd ? *o.sim.kd : *step.kd);
    if (o.script) c += " --script " + *o.script;
    c += " --duration " + number(step.duration) + " --out step" + std::to_string(k + 1);
    s += "\n  step " + std::to_string(k + 1) + ": " + c;
  }
  return s;
}

// The options that do not go together, and each one's range; the frame's size.
void check_render_options(const RenderOptions& o, int& width, int& height) {
  if (o.out.has_value() == o.video.has_value())
    throw InputError("render: give exactly one of --out DIR (PNG frames) and --video FILE.mp4");
  if (o.lesson.has_value() == !o.scene.empty())
    throw InputError("render: give a SCENE or --lesson NAME (springlab lesson list), and not both");
  if (o.lesson && (o.script || o.compare || o.sim.method || o.sim.dt || o.sim.substeps ||
                   o.sim.ks || o.sim.kd || !o.sim.sets.empty()))
    throw InputError(lesson_takes_its_values(o));
  parse_size(*o.size, width, height);
  if (o.compare_layout) draw::parse_compare_layout(*o.compare_layout, "--compare-layout");
  check_option("--fps", o.fps, 1.0, 240.0, false);
  if (o.ui_scale) check_option("--ui-scale", *o.ui_scale, 0.5, 4.0, false);
  if (o.frames) check_option("--frames", static_cast<double>(*o.frames), 1, 1e7, false);
  if (o.duration) check_option("--duration", *o.duration, 0.0, 1e6, true, " s");
  if (o.video && (width % 2 || height % 2))
    throw InputError("--size: a video needs an even width and height (yuv420p), got " + *o.size);
}

// --select's frame numbers, separated by commas.
std::set<std::int64_t> parse_select(const std::string& text) {
  std::set<std::int64_t> selected;
  std::stringstream s(text);
  for (std::string item; std::getline(s, item, ',');) {
    char* end = nullptr;
    const long long k = std::strtoll(item.c_str(), &end, 10);
    if (item.empty() || *end || k < 0)
      throw InputError("--select: frame numbers separated by commas, got '" + text + "'");
    selected.insert(k);
  }
  return selected;
}

// What to render: one scene (its session made now), or a lesson's steps one after another (each
// step's session made as the step starts); the frames in all, cut by --duration and --frames.
struct Plan {
  std::vector<Shot> shots;
  std::optional<Lesson> lesson;
  int lesson_number = 0, lesson_count = 0;
  std::string name;
  std::int64_t frames = 0;
};

Plan plan_shots(const RenderOptions& o, float scale) {
  Plan plan;
  std::vector<Shot>& shots = plan.shots;
  std::optional<Lesson>& lesson = plan.lesson;
  int& lesson_number = plan.lesson_number;
  int& lesson_count = plan.lesson_count;
  std::string& name = plan.name;
  std::int64_t& frames = plan.frames;
  if (o.lesson) {
    lesson = open_lesson(*o.lesson);
    lesson_count = static_cast<int>(shipped_lesson_files().size());
    lesson_number = course_number(*lesson);
    name = "lesson " + lesson->name;
    shots.resize(lesson->steps.size());  // made as each step starts
    for (std::size_t k = 0; k < shots.size(); ++k) {
      shots[k].frames = std::max<std::int64_t>(1, std::llround(lesson->steps[k].duration * o.fps));
      frames += shots[k].frames;
    }
    if (o.duration)
      frames = std::min(frames, std::max<std::int64_t>(1, std::llround(*o.duration * o.fps)));
    if (o.frames) frames = std::min(frames, *o.frames);
  } else {
    Prepared p = prepare(o.scene, o.sim);
    // --compare names the scene kind's rows: methods, or an IK scene's solvers.
    std::vector<int> compare;
    if (o.compare) compare = make_scene_kind(p.scene)->lanes_named(*o.compare, "--compare");
    std::optional<Script> script;
    if (o.script) script = load_script(*o.script, p.scene);
    const double duration = o.duration ? *o.duration
                            : script   ? std::max(script->end_time() + 1.0, 1.0)
                                       : p.scene.duration;
    frames = o.frames ? *o.frames : std::max<std::int64_t>(1, std::llround(duration * o.fps));
    name = p.scene.name;
    Shot shot;
    shot.session = std::make_unique<Session>(std::move(p.scene), p.settings, o.fps);
    if (!compare.empty()) shot.session->set_compare_rows(compare);
    if (script) shot.session->play(*script);
    for (Lane& lane : shot.session->lanes()) warn_if_unstable(lane.sim, name);
    shot.ui = shot_ui(*shot.session, name, scale);
    if (o.compare_layout)
      shot.ui.view.compare_layout =
          draw::parse_compare_layout(*o.compare_layout, "--compare-layout");
    shot.frames = frames;
    shots.push_back(std::move(shot));
  }
  return plan;
}

// A scene's run at its end: each lane's sub-steps, and each lane that diverged or went unstable.
// One lane: kDiverged, its reason on stderr (the frames from then on show it stopped). Compare: a
// lane that diverged is the lesson, said on stdout; kDiverged only when none is left running.
int lane_verdicts(Session& session, const std::string& name) {
  for (const Lane& lane : session.lanes())
    std::printf("substeps   %s: %d (%s)\n", method_info(lane.sim.settings().method).name,
                lane.sim.settings().substeps,
                !lane.sim.auto_substeps()    ? "fixed"
                : lane.sim.substeps_capped() ? "auto, capped"
                                             : "auto");
  int running = 0;
  const Divergence* first = nullptr;
  for (Lane& lane : session.lanes()) {
    if (lane.sim.diverged()) lane.sim.explain_divergence();
    const Divergence* trouble = lane.sim.trouble();
    running += !lane.sim.diverged();
    if (!trouble) continue;
    if (!first) first = trouble;
    if (session.comparing()) {
      std::printf("%-10s %s: %s", lane.sim.diverged() ? "diverged" : "unstable",
                  app::lane_name(lane).c_str(), trouble->message().c_str());
      if (lane.sim.diverged())
        std::printf(" Drawn from then on as it was at t = %.4g s.", lane.sane.t);
      std::printf("\n");
    }
  }
  if (!first || (session.comparing() && running > 0)) return kOk;
  std::fflush(stdout);
  std::fprintf(stderr, "springlab: %s: %s\n", name.c_str(), first->message().c_str());
  return kDiverged;
}

// The frames written and the times they show, e.g. "frames 60 to 300, t = 1 to 5 s".
std::string frames_written(std::int64_t first, std::int64_t last, double t_first, double t_last) {
  char s[160];
  if (first == last)
    std::snprintf(s, sizeof s, "frame %lld, t = %.4g s", static_cast<long long>(first), t_first);
  else
    std::snprintf(s, sizeof s, "frames %lld to %lld, t = %.4g to %.4g s",
                  static_cast<long long>(first), static_cast<long long>(last), t_first, t_last);
  return s;
}

// A shot's frame as it is now: the scene's views (compare apart: a view each), the panels where
// asked, a lesson's chart and band, the overlay.
// With `faults`: what of its text does not fit (ui/text_fit.hpp) is added to it.
void draw_shot(gfx::Offscreen& offscreen, Shot& shot, const ui::FrameStats& stats, bool panels,
               int width, int height, float scale, std::vector<std::string>* faults) {
  Session& session = *shot.session;
  if (shot.band)
    shot.ui.band = ui::lesson_band_height(*shot.band, static_cast<float>(width), scale);
  const draw::Viewport viewport = panels || shot.band
                                      ? ui::scene_viewport(shot.ui, session, width, height)
                                      : draw::Viewport{0, 0, width, height};
  const std::vector<draw::LaneView> views =
      draw::lane_views(session, shot.ui.view.camera, shot.ui.view.compare_layout, viewport);
  std::vector<draw::Frame> pictures;
  pictures.reserve(views.size());
  for (const draw::LaneView& view : views)
    pictures.push_back(draw::build_frame(session, shot.ui.view, view));
  offscreen.draw(pictures, [&] {
    if (panels) ui::draw_panels(session, shot.ui, stats, width, height);
    if (shot.accuracy)  // where the layout puts it, as in the app's lesson
      ui::draw_compare_panel(*shot.accuracy, session, scale,
                             ui::accuracy_rect(shot.ui, session, width, height), width, height);
    if (shot.band) {
      shot.band->elapsed = session.simulated_target() / session.speed();  // (as the app's)
      ui::draw_lesson_band(*shot.band, static_cast<float>(width), scale);
    }
    ui::OverlayOptions overlay;
    overlay.scale = scale;
    overlay.caption = !panels;
    overlay.trails = shot.ui.view.trails;
    ui::draw_overlay(session, views, viewport, shot.ui.scene_name, overlay);
  });
  if (faults && ImGui::GetCurrentContext() && ImGui::GetDrawData())
    for (std::string& fault :
         ui::text_faults(ui::text_runs(*ImGui::GetDrawData(), *ImGui::GetIO().Fonts),
                         ui::windows_of(*ImGui::GetDrawData())))
      faults->push_back(std::move(fault));
}

// The output, made before any work: a folder that cannot be written, or no ffmpeg, fails first.
std::unique_ptr<FrameWriter> open_output(const RenderOptions& o, int width, int height,
                                         MadeFolder& folder) {
  if (!o.out) return mp4_video(*o.video, width, height, o.fps);
  std::error_code ec;
  folder.path = *o.out;
  folder.made = std::filesystem::create_directories(*o.out, ec);
  if (ec || !std::filesystem::is_directory(*o.out))
    throw InputError("--out: cannot create the folder '" + *o.out + "' (" + ec.message() + ")");
  return png_sequence(*o.out);
}

// The shot frame k shows, brought to it: a lesson's next step made at its first frame (the one
// before let go); otherwise its session advanced a frame past the shot's first, the work counted.
Shot& shot_for_frame(Plan& plan, std::int64_t k, std::size_t& current, std::int64_t& shot_start,
                     ui::FrameStats& stats, double fps, float scale) {
  std::vector<Shot>& shots = plan.shots;
  if (k - shot_start >= shots[current].frames) {  // the next step of a lesson
    shot_start += shots[current].frames;
    shots[current].session.reset();
    ++current;
  }
  Shot& shot = shots[current];
  if (!shot.session) {
    shot = lesson_shot(*plan.lesson, static_cast<int>(current), plan.lesson_number,
                       plan.lesson_count, fps, scale);
  } else if (k > shot_start) {
    Session& session = *shot.session;
    const std::vector<Counters> before = ui::lane_counters(session);
    const auto t0 = std::chrono::steady_clock::now();
    session.advance_frame();
    stats.sim_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ui::count_frame(stats, session, before);
  }
  return shot;
}

// --check-text's verdict over the run's: text that does not fit fails a run that went well.
int with_text_faults(int verdict, std::size_t text_faults) {
  if (text_faults == 0) return verdict;
  std::fflush(stdout);
  std::fprintf(stderr,
               "springlab: render --check-text: %zu piece%s of text do%s not fit its place (listed "
               "above as 'text')\n",
               text_faults, text_faults == 1 ? "" : "s", text_faults == 1 ? "es" : "");
  return verdict == kOk ? kFailure : verdict;
}

// Frame k drawn from `shot` (draw_shot), with --check-text's faults printed, one a line; returns
// how many there were, and sets `draw_ms` to the time the drawing took.
std::size_t render_draw_frame(gfx::Offscreen& offscreen, Shot& shot, const ui::FrameStats& stats,
                              bool panels, int width, int height, float scale, bool check_text,
                              std::int64_t k, double& draw_ms) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> faults;
  draw_shot(offscreen, shot, stats, panels, width, height, scale, check_text ? &faults : nullptr);
  for (const std::string& fault : faults)
    std::printf("text       frame %lld: %s\n", static_cast<long long>(k), fault.c_str());
  draw_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return faults.size();
}

// The closing lines: the frames written, of what, at what size and rate, the times they show
// (`span`), the wall time since `start` and the frames a second, the renderer; then the output.
void render_print_summary(const RenderOptions& o, const std::string& name, int width, int height,
                          std::int64_t written, const std::string& span,
                          std::chrono::steady_clock::time_point start,
                          const std::string& renderer) {
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "rendered %lld frame%s of %s (%dx%d, %g frames/s: %s) in %.3g s: %.3g frames/s, on %s\n",
      static_cast<long long>(written), written == 1 ? "" : "s", name.c_str(), width, height, o.fps,
      span.c_str(), wall, wall > 0 ? written / wall : 0.0, renderer.c_str());
  std::printf("output     %s\n", (o.out ? *o.out : *o.video).c_str());
}

int render(const RenderOptions& o) {
  int width = 0, height = 0;
  check_render_options(o, width, height);
  const std::set<std::int64_t> selected =
      o.select ? parse_select(*o.select) : std::set<std::int64_t>{};
  const float scale = static_cast<float>(o.ui_scale ? *o.ui_scale : std::max(0.6, height / 720.0));
  use_language(check_language(o.lang, "--lang"));

  // What to render: one scene, or a lesson's steps one after another.
  Plan plan = plan_shots(o, scale);
  const std::optional<Lesson>& lesson = plan.lesson;
  const std::int64_t frames = plan.frames;
  if (!selected.empty() && *selected.rbegin() >= frames)
    throw InputError("--select: frame " + std::to_string(*selected.rbegin()) +
                     " is past the last frame (" + std::to_string(frames - 1) + ")");
  // A lesson is drawn with the panels (its chart is the point of many steps) under its band.
  const bool panels = o.ui || lesson;
  MadeFolder folder;
  std::unique_ptr<FrameWriter> writer = open_output(o, width, height, folder);

  // Dear ImGui draws the panels (--ui) and, always, the caption and the compare legend.
  gfx::Offscreen offscreen(o.software, width, height, scale, o.fps);
  // Mesa's software rasteriser draws with every core, and ffmpeg encodes beside it: the
  // simulation takes one core unless told (threads waiting for work would only take turns away).
  if (!o.sim.threads && gfx::software_renderer(offscreen.renderer_name())) set_thread_count(1);
  Progress progress("render " + plan.name, frames);
  ui::FrameStats stats;
  stats.timed = false;  // the same pixels for the same inputs
  const auto start = std::chrono::steady_clock::now();
  std::int64_t written = 0;
  // Frame k is drawn, then the simulation advances to frame k + 1 while the rasteriser's threads
  // draw it, then it is read back and handed to the writer (rows as GL reads them: the writer
  // puts them in order as it writes).
  std::optional<std::int64_t> drawn;
  std::size_t text_faults = 0;  // --check-text: pieces of text that do not fit
  std::optional<std::int64_t>
      first_written;  // the first and last frames drawn, and the times they show
  std::int64_t last_written = 0;
  double t_first = 0.0, t_last = 0.0;
  double draw_ms = 0.0;
  const auto collect = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    Image image = writer->spare();
    offscreen.read(image, true);
    stats.draw_ms =
        draw_ms +
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    writer->push(std::move(image), static_cast<int>(*drawn));
    ++written;
    progress.update(*drawn + 1);
    drawn.reset();
  };
  std::size_t current = 0;
  std::int64_t shot_start = 0;  // the frame the current shot starts at
  for (std::int64_t k = 0; k < frames; ++k) {
    Shot& shot = shot_for_frame(plan, k, current, shot_start, stats, o.fps, scale);
    if (drawn) collect();
    if (!selected.empty() && !selected.count(k)) continue;
    Session& session = *shot.session;
    text_faults += render_draw_frame(offscreen, shot, stats, panels, width, height, scale,
                                     o.check_text, k, draw_ms);
    drawn = k;
    // The time the frame shows: a scene's simulated time (its caption's), a lesson's presentation
    // time.
    const double shown = lesson ? static_cast<double>(k) / o.fps : session.simulated_target();
    if (!first_written) first_written = k, t_first = shown;
    last_written = k, t_last = shown;
  }
  if (drawn) collect();
  writer->finish();
  progress.finish();
  render_print_summary(o, plan.name, width, height, written,
                       frames_written(first_written.value_or(0), last_written, t_first, t_last),
                       start, offscreen.renderer_name());
  // (a lesson's steps diverge where they mean to)
  const int verdict = lesson ? kOk : lane_verdicts(*plan.shots[current].session, plan.name);
  return o.check_text ? with_text_faults(verdict, text_faults) : verdict;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* c =
      app.add_subcommand("render", "headless frames (PNG) or video (mp4), no display needed");
  c->add_option("scene", o->scene, "scene name or JSON file (or --lesson)");
  c->add_option("--lesson", o->lesson,
                "record a lesson, its captions burned in (springlab lesson list), with its own "
                "values: its captions "
                "state them, so it takes no --dt, --ks, --kd, --method or --compare (the message "
                "gives each step's "
                "scene to render with yours)");
  add_sim_options(*c, o->sim, false);
  c->add_option("--out", o->out, "write frame_00000.png, ... into this folder");
  c->add_option("--video", o->video, "write an mp4 (H.264) through ffmpeg");
  c->add_option("--frames", o->frames,
                "number of frames (default: the scene's duration, or the script's)");
  c->add_option("--duration", o->duration, "seconds of presentation time to render");
  c->add_option("--fps", o->fps, "frames per second (default 60)");
  c->add_option("--size", o->size, "WIDTHxHEIGHT (default 1280x720)");
  c->add_flag("--ui", o->ui, "include the app's panels");
  c->add_option("--ui-scale", o->ui_scale, "size of the panels and text (default: height / 720)");
  c->add_option("--lang", o->lang,
                "language of the panels and captions: " + language_list() + " (default en)");
  c->add_option("--script", o->script, "play a scripted demo (JSON)");
  c->add_option(
      "--compare", o->compare,
      "2 to 4 methods side by side, e.g. euler,verlet (IK scenes: solvers, e.g. ccd,fabrik,dls)");
  c->add_option("--compare-layout", o->compare_layout, kCompareLayoutHelp);
  c->add_option("--select", o->select, "write only these frames, e.g. 0,60,120");
  c->add_flag("--check-text", o->check_text,
              "say each piece of text that overlaps other text, is cut by its widget or shortened, "
              "and exit 1 if any");
  c->add_flag("--software", o->software,
              "use the software rasteriser even with a GPU (same pixels everywhere)");
  return [o] { return render(*o); };
}

}  // namespace springlab::app
