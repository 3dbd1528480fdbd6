#include "web/access.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <tuple>

#include "chart/chart_text.hpp"
#include "chart/compare_charts.hpp"
#include "springlab/energy.hpp"
#include "springlab/momentum.hpp"
#include "springlab/text.hpp"
#include "ui/actions.hpp"
#include "ui/gauge_verdict.hpp"
#include "ui/interaction.hpp"
#include "ui/kind_panels.hpp"
#include "ui/lesson_band.hpp"
#include "ui/live_charts.hpp"
#include "ui/physics_controls.hpp"

namespace springlab::app::web {

namespace {

// A number for JSON: a diverged run's infinity or NaN as null.
nlohmann::json finite(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

const char* tone_name(ui::Tone tone) {
  switch (tone) {
    case ui::Tone::Safe:
      return "safe";
    case ui::Tone::Near:
      return "near";
    case ui::Tone::Beyond:
      return "beyond";
    default:
      return "neutral";
  }
}

}  // namespace

std::vector<chart::Chart> charts(const InteractiveApp& app) {
  const Session& session = app.session();
  std::vector<chart::Chart> out =
      ui::kind_panels(session.kind()).charts_said(session);  // the kind's own
  // The accuracy panel's charts, once its sweep has runs: the work-precision charts' slopes.
  if (app.accuracy().open) {
    const SweepResult result = app.accuracy().sweep.snapshot();
    if (!result.runs.empty())
      for (chart::NamedChart& c : chart::compare_charts(result, session.scene().name))
        out.push_back(std::move(c.chart));
  }
  return out;
}

namespace {

// The words of the document's own controls and headings, in the app's language (the row's noun
// the scene kind's: "method", or an IK scene's "solver").
nlohmann::json describe_labels(const Session& session) {
  return {{"pause", tr("Pause (space)")},
          {"resume", tr("Resume (space)")},
          {"step", tr("Step (S)")},
          {"reset", tr("Reset (R)")},
          {"scene", tr("scene")},
          {"method", tr(session.kind().row_noun())},
          {"back", tr("\u2190 Back")},
          {"next", tr("Next \u2192")},
          {"energy", tr("Energy")},
          {"sound", tr("Hear the energy of")},
          {"csv", tr("Download its data (CSV)")},
          {"particle", tr("particle")},
          {"hold", tr("Hold it")},
          {"release", tr("Let go")},
          {"left", tr("left")},
          {"right", tr("right")},
          {"up", tr("up")},
          {"down", tr("down")}};
}

}  // namespace

std::string describe(const InteractiveApp& app) {
  using nlohmann::json;
  const Session& session = app.session();
  const ui::UiState& ui = app.ui();
  json d = {{"scene", app.scene_name()},  {"description", tr(session.scene().description)},
            {"scenes", ui.scenes},        {"method", lane_row(session.primary()).name},
            {"paused", session.paused()}, {"t", session.primary().sim.state().t},
            {"message", ui.message}};
  d["methods"] = json::array();
  d["lanes"] = json::array();
  // The rows the select offers: the kind's (methods, or an IK scene's solvers).
  for (int k = 0; k < session.kind().row_count(); ++k) {
    const LaneRow row = session.kind().row(k);
    d["methods"].push_back({{"name", row.name}, {"label", tr(row.label)}});
  }
  d["controls"] = json::array();
  for (const ui::PhysicsControl& c : ui::physics_controls(session, ui))
    d["controls"].push_back({{"id", c.id},
                             {"label", c.label},
                             {"value", c.value},
                             {"lo", c.lo},
                             {"hi", c.hi},
                             {"log", c.log}});
  for (const Lane& lane : session.lanes()) {
    const StabilityAnalysis* analysis = lane.analysis ? lane.analysis.get() : nullptr;
    const ui::GaugeVerdict verdict = ui::gauge_verdict(lane, analysis, false);
    const double e = energy(lane.sim.model(), lane.sim.state()).total();
    // Where it started and the scene's scale of energy: what the sound measures its change by.
    const State& start = session.scene().state;
    const bool same_start = start.x.rows() == lane.sim.state().x.rows();
    d["lanes"].push_back(
        {{"label", lane_label(lane)},
         {"t", lane.sim.state().t},
         {"verdict", verdict.text},
         {"tone", tone_name(verdict.tone)},
         {"diverged", lane.sim.diverged()},
         {"why", lane.sim.divergence() ? lane.sim.divergence()->reason : ""},
         {"energy", finite(e)},
         {"energy0", finite(same_start ? energy(lane.sim.model(), start).total() : e)},
         {"scale", same_start ? energy_scale(lane.sim.model(), start) : 1.0}});
  }
  d["particles"] = session.primary().sim.state().particle_count();
  d["held"] = session.grabbed();
  if (session.grabbed() >= 0) {  // where it is (the first lane's), m
    const auto x = session.primary().sim.state().x.row(session.grabbed());
    d["held_at"] = {finite(x(0)), finite(x(1)), finite(x(2))};
  }
  d["lesson"] = nullptr;
  if (app.lesson()) {
    const ui::LessonBand b =
        ui::band_of(*app.lesson(), app.step(), 0, 0);  // (its words in the app's language)
    d["lesson"] = {{"title", b.title},
                   {"step", app.step() + 1},
                   {"steps", app.lesson()->steps.size()},
                   {"step_title", b.step_title},
                   {"caption", b.caption},
                   {"prompt", b.prompt}};
  }
  d["charts"] = json::array();
  for (const chart::Chart& c : charts(app))
    d["charts"].push_back({{"title", c.title}, {"summary", chart::describe_chart(c)}});
  d["labels"] = describe_labels(session);
  // (text that is not UTF-8, a file's, is replaced rather than thrown on)
  return d.dump(-1, ' ', false, json::error_handler_t::replace);
}

bool control(InteractiveApp& app, const std::string& name, double value) {
  // A particle held and moved by keyboard, as a drag holds and moves it: "hold" (its index),
  // "left", "right", "up", "down" (a twentieth of the scene a press, in the view's plane),
  // "release".
  if (name == "hold") {
    const int i = static_cast<int>(value);
    if (!(value >= 0) || i >= app.session().primary().sim.state().particle_count()) return false;
    app.control([i](Session& s, ui::UiState&) { ui::hold(s, i); });
    return true;
  }
  if (name == "release") {
    app.control([](Session& s, ui::UiState&) { s.release(); });
    return true;
  }
  for (const auto& [key, x, y] : {std::tuple{"left", -1, 0}, std::tuple{"right", 1, 0},
                                  std::tuple{"up", 0, 1}, std::tuple{"down", 0, -1}})
    if (name == key) {
      app.control([x = x, y = y](Session& s, ui::UiState&) { ui::nudge(s, x, y); });
      return true;
    }

  if (name == "next") {
    if (app.lesson()) app.next_step();
    return true;
  }
  if (name == "back") {
    if (app.lesson()) app.previous_step();
    return true;
  }
  if (name == "pause") {
    app.control([value](Session& s, ui::UiState&) { s.set_paused(value != 0.0); });
    return true;
  }
  if (name == "step" || name == "reset") {
    const ui::Action action = name == "step" ? ui::Action::Step : ui::Action::Reset;
    app.control([action](Session& s, ui::UiState& ui) { ui::perform(action, s, ui); });
    return true;
  }
  for (const ui::PhysicsControl& c : ui::physics_controls(app.session(), app.ui()))
    if (name == c.id) {
      if (!std::isfinite(value)) return false;
      const double v = std::clamp(value, c.lo, c.hi);
      app.control([id = std::string(c.id), v](Session& s, ui::UiState& ui) {
        for (const ui::PhysicsControl& now : ui::physics_controls(s, ui))
          if (id == now.id) now.set(s, v);
      });
      return true;
    }
  return false;
}

bool choose(InteractiveApp& app, const std::string& what, const std::string& name) {
  if (what == "method") {
    const std::optional<int> row =
        app.session().kind().find(name);  // a method, or an IK scene's solver
    if (!row) return false;
    app.control([row](Session& s, ui::UiState&) { s.choose(*row); });
    return true;
  }
  if (what == "scene") {
    app.open_after_frame(name);
    return true;
  }
  return false;
}

std::string homework_words() {
  return nlohmann::json{
      {"title", tr("Homework 8: the rope in JavaScript")},
      {"code", tr("Your simulateEuler and simulateVerlet (the rope: rope.masses, rope.springs)")},
      {"run", tr("Check and run")},
      {"starter", tr("Starter code")},
      {"close", tr("Close")},
      {"checking", tr("checking...")}}
      .dump();
}

std::string homework_result(const homework::Report& report) {
  // (A crash's last printed lines may hold any bytes: replaced, never thrown.)
  return nlohmann::json{{"text", homework::format_report(report)}, {"failed", report.failed()}}
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace springlab::app::web
