// springlab [view [SCENE]]: the interactive app. With --frames N it runs N frames, as fast as they
// come, optionally writes a screenshot of the window, prints what happened and exits: how the
// tests (under xvfb-run) and a course's CI use it.
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "lesson/lesson_library.hpp"
#include "springlab/error.hpp"
#include "util/language.hpp"
#include "window/window_app.hpp"

namespace springlab::app {

namespace {

struct ViewCli {
  AppSettings app;
  WindowOptions window;
  std::optional<std::string> compare, compare_layout, size;
  std::optional<long> frames;
};

int view(ViewCli& o) {
  if (o.frames) check_option("--frames", static_cast<double>(*o.frames), 1, 1e7, false);
  o.window.frames = o.frames;
  check_option("--ui-scale", o.app.ui_scale, 0.5, 4.0, false);
  if (!o.app.language.empty()) o.app.language = check_language(o.app.language, "--lang");
  if (o.window.msaa != -1) check_option("--msaa", o.window.msaa, 0, 16, false);
  if (o.window.screenshot && !o.frames)
    throw InputError(
        "--screenshot: needs --frames N (the screenshot is taken after the N-th frame)");
  if (o.size) {
    char x = 0;
    std::istringstream s(*o.size);
    if (!(s >> o.window.width >> x >> o.window.height) || x != 'x' || !s.eof() ||
        o.window.width < 320 || o.window.height < 240 || o.window.width > 7680 ||
        o.window.height > 4320)
      throw InputError("--size: must be WIDTHxHEIGHT, from 320x240 to 7680x4320, got '" + *o.size +
                       "'");
  }
  o.app.compare =
      o.compare;  // (its names are the scene kind's rows: checked once the scene is read)
  if (o.compare_layout)
    o.app.compare_layout = draw::parse_compare_layout(*o.compare_layout, "--compare-layout");
  // A lesson is checked before any window opens: a bad one is bad input, display or not.
  if (o.app.lesson) check_lesson_step(open_lesson(*o.app.lesson), o.app.lesson_step, "--step");
  o.window.threads_given = o.app.sim.threads.has_value();
  if (o.window.homework && o.compare)
    throw InputError(
        "--homework: shows your rope's lanes beside springlab's; it does not go with --compare");
  return run_window(o.app, o.window);
}

void add_options(CLI::App& c, ViewCli& o) {
  add_sim_options(c, o.app.sim, false);
  c.add_option("--script", o.app.script, "play a scripted demo (JSON)");
  c.add_option("--compare", o.compare,
               "start in compare mode with 2 to 4 methods, e.g. euler,verlet");
  c.add_option("--compare-layout", o.compare_layout, kCompareLayoutHelp);
  c.add_option("--frames", o.frames, "run N frames, then exit (with --screenshot: write one)");
  c.add_option("--screenshot", o.window.screenshot,
               "after --frames N frames, write the window to this PNG");
  c.add_option("--keys", o.window.keys,
               "press these keys, one every other frame from the third, e.g. F6,Down,Space (the "
               "panels by keyboard, scripted)");
  c.add_option("--ui-scale", o.app.ui_scale,
               "size of the panels and text (times the monitor's scale)");
  c.add_option(
      "--lang", o.app.language,
      "language of the panels and lessons: " + language_list() + " (default: LANG, LC_MESSAGES)");
  c.add_option("--size", o.size, "window size WIDTHxHEIGHT (default 1280x720)");
  c.add_flag("--accuracy", o.app.accuracy,
             "open the accuracy-against-cost panel and start its sweep");
  c.add_flag("--region", o.app.region, "open the stability region (key G), as a link's region=1");
  c.add_option("--lesson", o.app.lesson,
               "teach a lesson: a name or number from `springlab lesson list`, or a file");
  c.add_option("--step", o.app.lesson_step, "start the lesson at this step (from 1)");
  c.add_option("--msaa", o.window.msaa,
               "multisampling (default: 4 on a GPU, 0 on a software rasteriser)");
  c.add_option("--homework", o.window.homework,
               "your rope.cpp (homework 8): its simulateEuler and simulateVerlet as lanes beside "
               "springlab's, rebuilt when saved");
}

}  // namespace

Command add_view_command(CLI::App& app) {
  auto o = std::make_shared<ViewCli>();
  CLI::App* c = app.add_subcommand("view", "the interactive app (opens a window)");
  c->add_option("scene", o->app.scene, "scene name or JSON file (default: rope)");
  add_options(*c, *o);
  return [o] { return view(*o); };
}

Command default_view_command() {
  return [] {
    ViewCli o;
    return view(o);
  };
}

}  // namespace springlab::app
