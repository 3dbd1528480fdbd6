#include "web/access.hpp"

#include <cmath>
#include <cstdio>
#include <tuple>

#include "springlab/energy.hpp"
#include "springlab/text.hpp"
#include "ui/actions.hpp"
#include "chart/chart_text.hpp"
#include "ui/gauge_verdict.hpp"
#include "ui/lesson_band.hpp"
#include "ui/live_charts.hpp"
#include "ui/physics_controls.hpp"

namespace springlab::app::web {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

const char* tone_name(ui::Tone tone) {
  switch (tone) {
    case ui::Tone::Safe: return "safe";
    case ui::Tone::Near: return "near";
    case ui::Tone::Beyond: return "beyond";
    default: return "neutral";
  }
}

}  // namespace

std::vector<chart::Chart> charts(const Session& session) {
  if (session.scene().ik) return {};  // (its chart is the solvers' distance: not yet said here)
  return {ui::energy_chart(session), ui::position_chart(session), ui::phase_chart(session)};
}

std::string describe(const InteractiveApp& app) {
  const Session& session = app.session();
  const ui::UiState& ui = app.ui();
  std::string json = "{\"scene\":" + quoted(app.scene_name());
  json += ",\"description\":" + quoted(tr(session.scene().description));
  json += ",\"scenes\":[";
  for (std::size_t i = 0; i < ui.scenes.size(); ++i) json += (i ? "," : "") + quoted(ui.scenes[i]);
  json += "],\"method\":" + quoted(method_info(session.method()).name) + ",\"methods\":[";
  bool first = true;
  for (const MethodInfo& m : methods()) {
    json += std::string(first ? "" : ",") + "{\"name\":" + quoted(m.name) + ",\"label\":" + quoted(tr(m.label)) + "}";
    first = false;
  }
  json += "],\"paused\":" + std::string(session.paused() ? "true" : "false");
  json += ",\"t\":" + number(session.primary().sim.state().t);
  json += ",\"controls\":[";
  first = true;
  for (const ui::PhysicsControl& c : ui::physics_controls(session, ui)) {
    json += std::string(first ? "" : ",") + "{\"id\":\"" + c.id + "\",\"label\":" + quoted(c.label) +
            ",\"value\":" + number(c.value) + ",\"lo\":" + number(c.lo) + ",\"hi\":" + number(c.hi) +
            ",\"log\":" + (c.log ? "true" : "false") + "}";
    first = false;
  }
  json += "],\"lanes\":[";
  first = true;
  for (const Lane& lane : session.lanes()) {
    const StabilityAnalysis* analysis = lane.analysis ? lane.analysis.get() : nullptr;
    const ui::GaugeVerdict verdict = ui::gauge_verdict(lane, analysis, false);
    const Energy e = energy(lane.sim.model(), lane.sim.state());
    // Where it started and the scene's scale of energy: what the sound measures its change by.
    const State& start = session.scene().state;
    const bool same_start = start.x.rows() == lane.sim.state().x.rows();
    const double e0 = same_start ? energy(lane.sim.model(), start).total() : e.total();
    const double scale = same_start ? energy_scale(lane.sim.model(), start) : 1.0;
    json += std::string(first ? "" : ",") + "{\"label\":" + quoted(lane_label(lane)) + ",\"t\":" + number(lane.sim.state().t) +
            ",\"verdict\":" + quoted(verdict.text) + ",\"tone\":\"" + tone_name(verdict.tone) + "\"" +
            ",\"diverged\":" + (lane.sim.diverged() ? "true" : "false") +
            ",\"why\":" + quoted(lane.sim.divergence() ? lane.sim.divergence()->reason : "") +
            ",\"energy\":" + number(e.total()) + ",\"energy0\":" + number(e0) + ",\"scale\":" + number(scale) + "}";
    first = false;
  }
  json += "],\"particles\":" + std::to_string(session.primary().sim.state().particle_count());
  json += ",\"held\":" + std::to_string(session.grabbed());
  if (session.grabbed() >= 0) {  // where it is (the first lane's), m
    const auto x = session.primary().sim.state().x.row(session.grabbed());
    json += ",\"held_at\":[" + number(x(0)) + "," + number(x(1)) + "," + number(x(2)) + "]";
  }
  json += ",\"lesson\":";
  if (app.lesson()) {
    const Lesson& l = *app.lesson();
    const ui::LessonBand b = ui::band_of(l, app.step(), 0, 0);  // (its words in the app's language)
    json += "{\"title\":" + quoted(b.title) + ",\"step\":" + std::to_string(app.step() + 1) +
            ",\"steps\":" + std::to_string(l.steps.size()) + ",\"step_title\":" + quoted(b.step_title) +
            ",\"caption\":" + quoted(b.caption) + ",\"prompt\":" + quoted(b.prompt) + "}";
  } else {
    json += "null";
  }
  json += ",\"charts\":[";
  first = true;
  for (const chart::Chart& c : charts(session)) {
    json += std::string(first ? "" : ",") + "{\"title\":" + quoted(c.title) + ",\"summary\":" + quoted(chart::describe_chart(c)) + "}";
    first = false;
  }
  json += "]";
  json += ",\"message\":" + quoted(ui.message);
  // The words of the document's own controls and headings, in the app's language.
  json += ",\"labels\":{\"pause\":" + quoted(tr("Pause (space)")) + ",\"resume\":" + quoted(tr("Resume (space)")) +
          ",\"step\":" + quoted(tr("Step (S)")) + ",\"reset\":" + quoted(tr("Reset (R)")) +
          ",\"scene\":" + quoted(tr("scene")) + ",\"method\":" + quoted(tr("method")) +
          ",\"back\":" + quoted(tr("\u2190 Back")) + ",\"next\":" + quoted(tr("Next \u2192")) +
          ",\"energy\":" + quoted(tr("Energy")) + ",\"sound\":" + quoted(tr("Hear the energy of")) +
          ",\"csv\":" + quoted(tr("Download its data (CSV)")) + ",\"particle\":" + quoted(tr("particle")) +
          ",\"hold\":" + quoted(tr("Hold it")) + ",\"release\":" + quoted(tr("Let go")) +
          ",\"left\":" + quoted(tr("left")) + ",\"right\":" + quoted(tr("right")) + ",\"up\":" + quoted(tr("up")) +
          ",\"down\":" + quoted(tr("down")) + "}";
  return json + "}";
}

namespace {

// How far a press moves a held particle: a twentieth of the scene's extent at its start.
double nudge(const Session& session) {
  const Points& x = session.scene().state.x;
  if (x.rows() == 0) return 0.05;
  const double extent = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  return extent > 0.0 ? extent / 20.0 : 0.05;
}

}  // namespace

bool control(InteractiveApp& app, const std::string& name, double value) {
  // A particle held and moved by keyboard, as a drag holds and moves it: "hold" (its index),
  // "left", "right", "up", "down" (a twentieth of the scene a press, in the view's plane), "release".
  if (name == "hold") {
    const int i = static_cast<int>(value);
    if (!(value >= 0) || i >= app.session().primary().sim.state().particle_count()) return false;
    app.control([i](Session& s, ui::UiState&) {
      s.grab(i);
      s.drag_to(s.primary().sim.state().x.row(i).transpose());
    });
    return true;
  }
  if (name == "release") {
    app.control([](Session& s, ui::UiState&) { s.release(); });
    return true;
  }
  for (const auto& [key, x, y] : {std::tuple{"left", -1, 0}, std::tuple{"right", 1, 0}, std::tuple{"up", 0, 1},
                                  std::tuple{"down", 0, -1}})
    if (name == key) {
      const Vec3 step(x, y, 0.0);
      app.control([step](Session& s, ui::UiState&) {
        if (s.grabbed() < 0 || !s.drag_target()) return;
        s.drag_to(*s.drag_target() + nudge(s) * step);
      });
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
    const std::optional<Method> m = find_method(name);
    if (!m) return false;
    app.control([m](Session& s, ui::UiState&) { s.set_method(*m); });
    return true;
  }
  if (what == "scene") {
    app.open_after_frame(name);
    return true;
  }
  return false;
}

}  // namespace springlab::app::web
