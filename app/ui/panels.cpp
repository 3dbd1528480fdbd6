// The app's panels, drawn with Dear ImGui each frame from the session and the UI's state. One
// function a window (draw_panels calls them in this order), as imgui_demo.cpp is laid out:
//
//   strip               the strip of buttons along the foot (a phone held upright)
//   controls_window     "springlab": pickers, the platform's controls, about, the scene kind's
//                       controls (kind_panels.hpp; here mass_spring_controls: method, transport,
//                       clocks, gauge per lane, parameters), tools (cost, the kind's tools: here
//                       panels' buttons and compare choices; a particle by keys, view and files)
//   charts_window       "Charts": the kind's (here energy, position, phase, the adaptive step),
//                       or a lesson's own
//   region              the stability region (region_window)
//   divergence_window   "Diverged": the single view's banner and the way out
//   message_window      "Message": a file that failed to load
//   keys_window         "Keys" (F1)
//
// The charts' contents (energy_chart, position_chart, ...) and the controls' parts (gauge,
// clocks, parameters, ...) are the functions above them.
#include "ui/panels.hpp"
#include "ui/kind_panels.hpp"
#include "ui/live_charts.hpp"
#include "ui/physics_controls.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>

#include "chart/imgui_chart.hpp"
#include "chart/stability_region.hpp"
#include "draw/palette.hpp"
#include "ui/gauge_verdict.hpp"
#include "ui/interaction.hpp"
#include "ui/layout.hpp"
#include "ui/overlay.hpp"
#include "ui/theme.hpp"
#include "chart/text_wrap.hpp"
#include "springlab/text.hpp"
#include "util/language.hpp"

namespace springlab::ui {

namespace {

constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                    ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
// The two docked panels sit where the scene is never drawn (scene_viewport), over the plain
// background: filling them again would only cost time (on a software rasteriser, most of a frame).
constexpr ImGuiWindowFlags kDocked = kPanel | ImGuiWindowFlags_NoBackground;

const ImVec4 kSafe = v4(kSafeText), kNear = v4(kNearText), kBeyond = v4(kBeyondText), kNeutral = v4(kNeutralText);

// This frame's panels are laid out for touch (ui/layout.hpp): no hover, thumbs.
bool g_touch = false;

// A slider; on a touch layout with - and + beside it, so that a thumb sets a value a step at a
// time (a logarithmic slider by x1.25, a linear one by a twentieth of its range).
bool slider(const char* label, double& value, double lo, double hi, bool log, const char* format = "%.3g") {
  const ImGuiSliderFlags flags = log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
  float v = static_cast<float>(value);
  if (!g_touch) {
    const bool changed = ImGui::SliderFloat(label, &v, static_cast<float>(lo), static_cast<float>(hi), format, flags);
    if (changed) value = v;
    return changed;
  }
  const std::string_view name(label);
  const std::string shown(name.substr(0, name.find("##")));
  const float button = ImGui::GetFrameHeight(), spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  const float width = ImGui::CalcItemWidth() - 2 * (button + spacing);
  ImGui::PushID(label);
  double next = value;
  if (ImGui::Button("-", ImVec2(button, button))) next = log ? value / 1.25 : value - (hi - lo) / 20;
  ImGui::SameLine(0, spacing);
  ImGui::SetNextItemWidth(std::max(width, button));
  if (ImGui::SliderFloat("##value", &v, static_cast<float>(lo), static_cast<float>(hi), format, flags)) next = v;
  ImGui::SameLine(0, spacing);
  if (ImGui::Button("+", ImVec2(button, button))) next = log ? std::max(value, lo > 0 ? lo : 1e-3 * hi) * 1.25 : value + (hi - lo) / 20;
  if (!shown.empty()) {
    ImGui::SameLine(0, spacing);
    ImGui::TextUnformatted(shown.c_str());
  }
  ImGui::PopID();
  next = std::clamp(next, lo, hi);
  const bool changed = next != value;
  value = next;
  return changed;
}

// The analysis a lane shows: the latest (in the background mode it may be of the scene a moment
// ago, while the next is made); made here if the session makes them where needed.
const StabilityAnalysis* shown_analysis(app::Session& session, app::Lane& lane) {
  if (lane.analysis) return lane.analysis.get();
  if (!session.background_analysis()) return &lane.sim.stability();
  return nullptr;
}

// The stability gauge of one lane: h against the method's limit on one row (the verdict on the
// next when it is long), and with `explain` the limit and the mode that sets it.
void gauge(app::Session& session, app::Lane& lane, float width, bool explain) {
  const Simulation& sim = lane.sim;
  const MethodInfo& m = method_info(sim.settings().method);
  const StabilityAnalysis* analysis = shown_analysis(session, lane);
  const StabilityLimit* limit = analysis ? &analysis->limit(m.id) : nullptr;
  const GaugeVerdict said = gauge_verdict(lane, analysis, explain);
  const double fraction = said.fraction;
  const std::string& verdict = said.text;
  const std::string& momentum_line = said.momentum;
  const ImVec4 color = said.tone == Tone::Safe ? kSafe : said.tone == Tone::Near ? kNear
                       : said.tone == Tone::Beyond ? kBeyond : kNeutral;
  const ImGuiStyle& style = ImGui::GetStyle();
  // The bars line up after the usual label ("Symplectic Euler"); a longer one pushes its bar on
  // ("Vertex block descent" was drawn under it).
  const std::string label = app::lane_label(lane);
  const float label_w = std::max(ImGui::CalcTextSize(tr("Symplectic Euler ")).x,
                                 ImGui::CalcTextSize((label + " ").c_str()).x);
  ImGui::TextColored(v4(draw::lane_color(lane)), "%s", label.c_str());
  ImGui::SameLine(label_w + style.WindowPadding.x);
  // The bar (the limit sits at two thirds of it), then the verdict; a verdict too long for the
  // row goes on the next.
  const float bar_w = width * 0.22f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float line_h = ImGui::GetTextLineHeight();
  const float bar_h = line_h * 0.7f;
  const ImVec2 q(p.x, p.y + 0.5f * (line_h - bar_h));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(q, ImVec2(q.x + bar_w, q.y + bar_h), ImGui::GetColorU32(ImGuiCol_FrameBg), 3.0f);
  dl->AddRectFilled(q, ImVec2(q.x + bar_w * static_cast<float>(fraction), q.y + bar_h), ImGui::GetColorU32(color), 3.0f);
  if (limit && std::isfinite(limit->h) && limit->h > 0.0) {
    const float x = q.x + bar_w / 1.5f;
    dl->AddLine(ImVec2(x, q.y - 3), ImVec2(x, q.y + bar_h + 3), IM_COL32_WHITE, 2.0f);
  }
  ImGui::Dummy(ImVec2(bar_w, line_h));
  same_line_if_fits(ImGui::CalcTextSize(verdict.c_str()).x);
  ImGui::PushTextWrapPos(0.0f);  // a verdict longer than the panel wraps, never clips
  ImGui::TextColored(color, "%s", verdict.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::IsItemHovered() && limit) ImGui::SetTooltip("%s", tr(m.stability));
  if (!explain || !limit) return;
  if (g_touch) text_wrapped_disabled(tr(m.stability));  // (no hover under a finger)
  if (!momentum_line.empty()) text_wrapped_disabled(momentum_line);
  if (analysis && !analysis->oscillates()) {
    text_wrapped_disabled(format_text(tr("no oscillating modes (%s); %s"), tr(analysis->no_modes_reason()).c_str(),
                                      describe(*limit).c_str()));
  } else if (limit->mode && std::isfinite(limit->h) && limit->h > 0.0) {
    char mode[96];
    std::snprintf(mode, sizeof mode, tr(" (its mode: %.4g rad/s, damping ratio %.2g)"), limit->mode->w,
                  limit->mode->damping_ratio());
    text_wrapped_disabled(describe(*limit) + mode);
  } else {
    text_wrapped_disabled(describe(*limit));
  }
}

std::vector<chart::Chart> region_charts(app::Session& session, std::string& none) {
  std::vector<chart::Chart> out;
  const StabilityAnalysis* analysis = shown_analysis(session, session.lanes()[0]);
  if (!analysis) {
    none = tr("analysing the scene's stability...");
    return out;
  }
  std::vector<chart::RegionLane> planes[2];
  for (app::Lane& lane : session.lanes())
    if (!method_info(lane.sim.settings().method).adaptive())
      planes[static_cast<int>(chart::region_plane(lane.sim.settings().method))].push_back(
          {lane.sim.settings().method, lane.sim.h()});
  for (int k = 0; k < 2; ++k)
    if (!planes[k].empty()) out.push_back(chart::stability_region(*analysis, planes[k]));
  if (out.empty()) none = tr("an adaptive method chooses its own steps: it has no region");
  return out;
}

// Charts side by side over the room left in the window.
void charts_row(const std::vector<chart::Chart>& shown, float width, float height) {
  const float w = (width - (shown.size() - 1) * ImGui::GetStyle().ItemSpacing.x) / std::max<std::size_t>(1, shown.size());
  for (std::size_t k = 0; k < shown.size(); ++k) {
    if (k > 0) ImGui::SameLine();
    chart::chart_widget(("##chart" + std::to_string(k)).c_str(), shown[k], ImVec2(w, height));
  }
}

void region_window(app::Session& session, UiState& ui, float x, float y, float width, float height) {
  if (!ui.region) return;
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
  if (!ImGui::Begin((tr("Stability region (G)") + std::string("###region")).c_str(), &ui.region, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  std::string none;
  std::vector<chart::Chart> shown = region_charts(session, none);
  if (!none.empty()) ImGui::TextDisabled("%s", none.c_str());
  const ImVec2 room = ImGui::GetContentRegionAvail();
  charts_row(shown, room.x, room.y);
  ImGui::End();
}

// The charts: energy, the watched particle's position (with the exact solution) and its phase
// plot side by side; one (energy) in presentation mode; in a lesson, the ones its step shows.
// For a class (presentation, lessons) the lines are thicker; the stability regions keep theirs.
void mass_spring_charts(app::Session& session, float width, float height, bool presentation, const std::vector<LessonChart>& only) {
  std::vector<chart::Chart> shown;
  std::string none;
  const float line = presentation || !only.empty() ? 3.0f : 0.0f;
  const auto add = [&](chart::Chart c) {
    if (line > 0.0f)
      for (chart::Series& s : c.series) s.width = line;
    shown.push_back(std::move(c));
  };
  for (LessonChart c : only) {
    if (c == LessonChart::Energy) add(energy_chart(session));
    if (c == LessonChart::Position) add(position_chart(session));
    if (c == LessonChart::Phase) add(phase_chart(session));
    if (c == LessonChart::Steps) add(steps_chart(session));
    if (c == LessonChart::Momentum) add(momentum_chart(session));
    if (c == LessonChart::Region)
      for (chart::Chart& r : region_charts(session, none)) shown.push_back(std::move(r));
  }
  if (only.empty()) {
    add(energy_chart(session));
    if (!presentation) {
      shown.push_back(position_chart(session));
      shown.push_back(phase_chart(session));
    }
  }
  if (shown.empty()) ImGui::TextDisabled("%s", none.c_str());
  charts_row(shown, width, height);
}


}  // namespace

Ranges Ranges::of(const app::Session& session) {
  Ranges r;
  r.ks = session.stiffness();
  r.kd = session.damping();
  r.dt = session.primary().sim.settings().dt;
  r.mass = session.mass();
  r.drag = session.primary().sim.model().drag;
  r.gravity = session.primary().sim.model().gravity.norm();
  return r;
}

std::vector<Method> compare_methods(const UiState& ui) {
  std::vector<Method> out;
  for (const MethodInfo& m : methods())
    if (ui.compare_choice.has(m.id) && out.size() < app::Session::kMaxLanes) out.push_back(m.id);
  return out;
}

namespace {
float layout_scale(const UiState& ui) { return ui.scale * (ui.presentation ? kPresentationScale : 1.0f); }
}  // namespace

draw::Viewport scene_viewport(const UiState& ui, int width, int height) {
  return panel_layout(ui, width, height).scene;
}

Rect lesson_chart_rect(const UiState& ui, const draw::Viewport& scene, int width, int height, float scale) {
  const Rect strip = panel_layout(ui, width, height).strip;
  const float foot = !strip.empty() && strip.y > static_cast<float>(scene.y) ? strip.y : static_cast<float>(height);
  const float pad = 8.0f * scale, x = static_cast<float>(scene.x), y = static_cast<float>(scene.y);
  return {x + pad, y + pad, static_cast<float>(width) - x - 2.0f * pad, foot - y - 2.0f * pad};
}

// Parts every kind's controls share (kind_panels.hpp).

void row_picker(app::Session& session, const char* label, bool coloured) {
  if (session.comparing()) return;
  const app::SceneKind& kind = session.kind();
  if (!ImGui::BeginCombo(label, app::lane_label(session.primary()).c_str())) return;
  const int chosen = session.chosen();
  for (int k = 0; k < kind.row_count(); ++k) {
    const app::LaneRow row = kind.row(k);
    const std::string text = std::to_string(k + 1) + "  " + tr(row.label);
    if (coloured) ImGui::PushStyleColor(ImGuiCol_Text, v4(draw::row_color(row)));
    if (ImGui::Selectable(text.c_str(), k == chosen)) session.choose(k);
    if (coloured) ImGui::PopStyleColor();
  }
  ImGui::EndCombo();
}

// Pause, step, reset: the buttons a class sees pressed most.
void transport(app::Session& session) {
  // (On one line where they fit; at a large UI scale, the next button on the next line.)
  const auto width = [](const char* label) { return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x; };
  if (ImGui::Button(session.paused() ? tr("Resume (space)") : tr("Pause (space)"))) session.set_paused(!session.paused());
  same_line_if_fits(width(tr("Step (S)")));
  if (ImGui::Button(tr("Step (S)"))) {
    session.set_paused(true);
    session.step_once();
  }
  same_line_if_fits(width(tr("Reset (R)")));
  if (ImGui::Button(tr("Reset (R)"))) session.reset();
}

// The time of each lane (in compare mode a diverged lane stopped at its own), the speed, and
// the real-time factor when the simulation cannot keep up.
void clocks(app::Session& session, const FrameStats& stats) {
  if (!session.comparing()) {
    ImGui::Text("t = %.3f s", session.primary().sim.state().t);
  } else {
    bool first = true;
    for (const app::Lane& lane : session.lanes()) {
      if (!first) ImGui::SameLine();
      first = false;
      ImGui::TextColored(lane.sim.diverged() ? kBeyond : v4(draw::lane_color(lane)), "%.3f",
                         lane.sim.state().t);
    }
    ImGui::SameLine();
    ImGui::TextDisabled("s");
  }
  if (session.paused()) {
    ImGui::SameLine();
    ImGui::TextColored(kNear, tr("paused"));
  }
  if (session.speed() != 1.0) {
    ImGui::SameLine();
    ImGui::TextColored(kNear, tr("slow motion x%g"), session.speed());
  }
  // The real-time factor of a running simulation (paused, the last one is stale), on the same
  // line if it fits there, else on the next.
  const std::string slow = realtime_text(stats.realtime);
  if (!slow.empty() && !session.paused()) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(slow.c_str()).x) ImGui::NewLine();
    ImGui::TextColored(kNear, "%s", slow.c_str());
  }
}

namespace {

// The sliders of the physics; `few`: only dt, k_s and k_d (presentation mode).
void parameters(app::Session& session, UiState& ui, bool few) {
  const float s = layout_scale(ui);
  Simulation& sim = session.lanes()[0].sim;
  double mu = session.friction();
  double tol = sim.settings().step.tolerance;
  const std::vector<PhysicsControl> controls = physics_controls(session, ui);
  // k_s, k_d and dt, then the sub-steps, then the rest (not in presentation mode).
  const auto draw = [&](const PhysicsControl& c) {
    double v = c.value;
    if (slider(c.label.c_str(), v, c.lo, c.hi, c.log, c.format)) c.set(session, v);
  };
  std::size_t next = 0;
  for (; next < controls.size() && std::string_view(controls[next].id) != "mass"; ++next) draw(controls[next]);
  // Sub-steps: chosen from each lane's limit ("auto (N)"), until the slider fixes them.
  int substeps = sim.settings().substeps;
  std::string shown = std::to_string(substeps);
  if (session.auto_substeps()) {
    bool bound = sim.substeps_provisional();
    if (session.comparing())
      for (std::size_t k = 1; k < session.lanes().size(); ++k) {
        shown += ", " + std::to_string(session.lanes()[k].sim.settings().substeps);
        bound |= session.lanes()[k].sim.substeps_provisional();
      }
    if (bound) shown += tr(", bound");  // from the quick bound until the analysis ends
    shown = format_text(tr("auto (%s)"), shown.c_str());
  }
  ImGui::PushItemWidth(ImGui::CalcItemWidth() - ImGui::CalcTextSize(tr("auto")).x - ImGui::GetFrameHeight() -
                       2 * ImGui::GetStyle().ItemInnerSpacing.x);
  if (ImGui::SliderInt("##substeps", &substeps, 1, 256, shown.c_str(), ImGuiSliderFlags_Logarithmic))
    session.set_substeps(substeps);
  ImGui::PopItemWidth();
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  bool automatic = session.auto_substeps();
  if (ImGui::Checkbox(tr("auto"), &automatic)) {
    if (automatic) session.set_auto_substeps();
    else session.set_substeps(sim.settings().substeps);
  }
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::TextUnformatted(tr("sub-steps"));
  for (const app::Lane& lane : session.lanes())
    if (lane.sim.auto_substeps() && lane.sim.substeps_capped() && lane.analysis) {
      const bool hopeless = lane.analysis->limit(lane.sim.settings().method).h == 0.0;
      text_wrapped(app::lane_name(lane) + ": " +
                       (hopeless ? tr("unstable at any step: sub-steps cannot help") : tr("sub-steps capped: still past its limit")),
                   kNear);
      break;
    }
  if (few) return;
  for (; next < controls.size(); ++next) draw(controls[next]);
  if (sim.model().has_colliders() && slider(tr("friction"), mu, 0.0, 2.0, false, "%.2f")) session.set_friction(mu);
  if (method_info(session.method()).adaptive() && slider(tr("tolerance"), tol, 1e-10, 1e-1, true, "%.1e"))
    session.set_tolerance(tol);
  if (method_info(session.method()).family == MethodFamily::Iterative) {
    // Iterations a step: the solver error against the cost (XPBD: passes over the springs).
    int iterations = iterations_for(session.method(), sim.settings().step);
    if (ImGui::SliderInt(tr("iterations"), &iterations, 1, 100, "%d", ImGuiSliderFlags_Logarithmic))
      session.set_iterations(std::clamp(iterations, 1, 10000));
  }
  int speed_exp = static_cast<int>(std::lround(std::log2(session.speed())));
  const char* speeds[] = {"1/16", "1/8", "1/4", "1/2", "1", "2", "4"};
  if (ImGui::SliderInt(tr("speed"), &speed_exp, -4, 2, speeds[speed_exp + 4])) session.set_speed(std::pow(2.0, speed_exp));
  (void)s;
}

}  // namespace

namespace {

// The touch layouts' strip: Upright's sheet folded to one row (its menu, play or pause, step, the
// method, dt), or Side's folded panel (its menu, play or pause, step, one above the other).
void strip(app::Session& session, UiState& ui, const PanelLayout& layout, float s) {
  const Rect& r = layout.strip;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("##strip", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  const bool row = layout.kind == LayoutKind::Upright;
  const float button = ImGui::GetFrameHeight();
  const auto next = [&] {
    if (row) ImGui::SameLine();
  };
  if (ImGui::Button("\u2261", ImVec2(button, button))) {  // the menu: all the controls
    if (row) ui.sheet_open = true;
    else ui.side_open = true;
  }
  next();
  if (ImGui::Button(session.paused() ? ">" : "||", ImVec2(button, button))) session.set_paused(!session.paused());
  next();
  if (ImGui::Button("S", ImVec2(button, button))) {
    session.set_paused(true);
    session.step_once();
  }
  if (row) kind_panels(session.kind()).strip(session, ui, button);  // the kind's tail: its row, ...
  (void)s;
  ImGui::End();
}

// The mass-spring kind's strip tail: the method and dt.
void mass_spring_strip(app::Session& session, UiState& ui, float button) {
  ImGui::SameLine();
  // The method's combo takes what the dt slider leaves: at least its two buttons and a
  // button's width of slider (a phone's row: they ran off its right edge).
  const float left = ImGui::GetContentRegionAvail().x;
  const float dt_least = 3.0f * button + 2.0f * ImGui::GetStyle().ItemInnerSpacing.x + ImGui::GetStyle().ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(button, std::min(0.45f * left, left - dt_least)));
  row_picker(session, "##method", false);
  ImGui::SameLine();
  double dt = session.primary().sim.settings().dt;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
  if (slider("##dt", dt, ui.ranges.dt / 100, std::min(1.0, std::max(0.1, ui.ranges.dt * 100)), true, "dt %.3g"))  // symbols
    session.set_dt(dt);
}

// Each window of the panels, a function (the index is at the top of this file).

// The scene's picker and the lessons' (a choice is a request, taken after the frame).
void pickers(const UiState& ui, Requests& requests) {
  if (!ui.scenes.empty() && ImGui::BeginCombo(tr("scene"), ui.scene_name.c_str())) {
    for (const std::string& name : ui.scenes)
      if (ImGui::Selectable(name.c_str(), name == ui.scene_name)) requests.load = name;
    ImGui::EndCombo();
  }
  // The lessons: the lecture, step by step (the band across the top then leads).
  if (!ui.lessons.empty()) {
    std::string current = tr("(none: explore freely)");
    // (Its number and title where they fit the box, else "4 of 13": never a title cut mid-word.)
    const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2.0f * ImGui::GetStyle().FramePadding.x;
    for (std::size_t k = 0; k < ui.lessons.size(); ++k)
      if (ui.lessons[k].first == ui.lesson) {
        current = std::to_string(k + 1) + "  " + tr(ui.lessons[k].second);
        if (ImGui::CalcTextSize(current.c_str()).x > room) {
          char s[64];
          std::snprintf(s, sizeof s, tr("%zu of %zu"), k + 1, ui.lessons.size());
          current = s;
        }
      }
    if (ImGui::BeginCombo(tr("lesson"), current.c_str())) {
      if (ImGui::Selectable(tr("(none: explore freely)"), ui.lesson.empty())) requests.lesson = "";
      for (std::size_t k = 0; k < ui.lessons.size(); ++k) {
        const std::string label = std::to_string(k + 1) + "  " + tr(ui.lessons[k].second);
        if (ImGui::Selectable(label.c_str(), ui.lessons[k].first == ui.lesson)) requests.lesson = ui.lessons[k].first;
      }
      ImGui::EndCombo();
    }
  }
}

// The scene's description: its first sentence, the rest on hover (on touch, all of it).
void about(const app::Session& session, float s) {
  const std::string text = tr(session.scene().description);
  const std::size_t stop = g_touch ? std::string::npos : text.find(". ");  // (touch: all of it, no hover)
  text_wrapped_disabled(stop == std::string::npos ? text : text.substr(0, stop + 1) + " (...)");
  if (ImGui::IsItemHovered() && stop != std::string::npos) {
    ImGui::BeginTooltip();
    text_wrapped(text, {}, 420.0f * s);
    ImGui::EndTooltip();
  }
}

// The mass-spring kind's controls: the method, play and step, the clocks, each lane's stability
// gauge and the parameters.
void mass_spring_controls(app::Session& session, UiState& ui, const FrameStats& stats, const PanelLayout& layout, bool few) {
  row_picker(session, tr("method"), true);
  transport(session);
  clocks(session, stats);
  // Stability: the gauge of each lane, under the method it judges.
  const float inner_w = layout.controls.w - 2 * ImGui::GetStyle().WindowPadding.x - ImGui::GetStyle().ScrollbarSize;
  for (app::Lane& lane : session.lanes()) gauge(session, lane, inner_w, !session.comparing());
  ImGui::Separator();
  parameters(session, ui, few);
}

// A particle held and moved without a pointer (ui/interaction.hpp: hold, nudge), for the
// keyboard's navigation of the panels: its number, Hold it or Let go, and four arrows that
// repeat while held.
void particle_by_keys(app::Session& session, UiState& ui) {
  const int n = session.primary().sim.state().particle_count();
  if (n == 0) return;
  ImGui::InputInt(tr("particle"), &ui.key_particle);
  ui.key_particle = std::clamp(ui.key_particle, 0, n - 1);
  if (session.grabbed() < 0) {
    if (ImGui::Button(tr("Hold it"))) hold(session, ui.key_particle);
    return;
  }
  if (ImGui::Button(tr("Let go"))) return release(session);
  ImGui::PushButtonRepeat(true);
  const std::tuple<const char*, ImGuiDir, double, double> arrows[] = {
      {"##left", ImGuiDir_Left, -1, 0}, {"##right", ImGuiDir_Right, 1, 0},
      {"##up", ImGuiDir_Up, 0, 1}, {"##down", ImGuiDir_Down, 0, -1}};
  for (const auto& [id, dir, dx, dy] : arrows) {
    ImGui::SameLine();
    if (ImGui::ArrowButton(id, dir)) nudge(session, dx, dy);
  }
  ImGui::PopButtonRepeat();
}

// The mass-spring kind's tools: the accuracy, region and tableau panels' buttons and the compare
// choices.
void mass_spring_tools(app::Session& session, UiState& ui, float s) {
  if (ImGui::Button(ui.accuracy ? tr("Hide accuracy (A)") : tr("Accuracy vs cost (A)"))) ui.accuracy = !ui.accuracy;
  ImGui::SameLine();
  if (ImGui::Button(ui.region ? tr("Hide region (G)") : tr("Stability region (G)"))) ui.region = !ui.region;
  if (ImGui::Button(ui.tableau ? tr("Hide your method (Y)") : tr("Your method (Y)"))) ui.tableau = !ui.tableau;
  if (ImGui::CollapsingHeader(tr("Compare methods"))) {
    if (ImGui::Button(session.comparing() ? tr("Single view (C)") : tr("Compare (C)"))) {
      if (session.comparing()) session.set_compare({});
      else if (compare_methods(ui).size() >= 2) session.set_compare(compare_methods(ui));
    }
    ImGui::SameLine();
    ImGui::TextDisabled(tr("tick 2 to 4:"));
    if (ImGui::BeginTable("compare", 2)) {
      for (const MethodInfo& m : methods()) {
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, v4(draw::method_color(m.id)));
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(3 * s, 1 * s));
        bool on = ui.compare_choice.has(m.id);
        if (ImGui::Checkbox(m.name, &on)) ui.compare_choice.set(m.id, on);
        ImGui::PopStyleVar();
        ImGui::PopStyleColor();
      }
      ImGui::EndTable();
    }
  }
}

// Below the controls: what a frame costs, the kind's tools (its studies and compare choices), a
// particle by keys and the view and files.
void tools(app::Session& session, UiState& ui, const FrameStats& stats, float s, Requests& requests) {
  if (stats.timed)
    ImGui::TextDisabled(tr("a frame: %.1f ms simulating, %.1f drawing"), stats.sim_ms, stats.draw_ms);
  else
    ImGui::TextDisabled(tr("a frame: %lld force evaluations"), static_cast<long long>(stats.force_evals));
  // Compare: each lane's part of it, in its colour, and how the lanes are shown.
  if (session.comparing()) {
    for (std::size_t k = 0; k < session.lanes().size() && k < stats.lanes.size(); ++k) {
      const app::Lane& lane = session.lanes()[k];
      const Counters& work = stats.lanes[k];
      const std::string label = app::lane_label(lane);
      const ImVec4 colour = lane.sim.diverged() ? kBeyond : v4(draw::lane_color(lane));
      char line[200];
      if (lane.sim.diverged())
        std::snprintf(line, sizeof line, tr("%s: none (it diverged)"), label.c_str());
      else if (work.solver_iterations > 0)
        std::snprintf(line, sizeof line, tr("%s: %lld force evaluations + %lld solver iterations"), label.c_str(),
                      static_cast<long long>(work.force_evals), static_cast<long long>(work.solver_iterations));
      else
        std::snprintf(line, sizeof line, tr("%s: %lld force evaluations"), label.c_str(), static_cast<long long>(work.force_evals));
      ImGui::Indent();
      text_wrapped(line, colour);
      ImGui::Unindent();
    }
    ImGui::TextUnformatted(tr("lanes:"));
    ImGui::SameLine();
    if (ImGui::RadioButton(tr("apart"), ui.view.compare_layout == draw::CompareLayout::Apart))
      ui.view.compare_layout = draw::CompareLayout::Apart;
    ImGui::SameLine();
    if (ImGui::RadioButton(tr("together"), ui.view.compare_layout == draw::CompareLayout::Together))
      ui.view.compare_layout = draw::CompareLayout::Together;
  }
  kind_panels(session.kind()).tools(session, ui, s);
  if (ImGui::CollapsingHeader(tr("A particle by keys"))) particle_by_keys(session, ui);
  if (ImGui::CollapsingHeader(tr("View and files"))) {
    ImGui::InputTextWithHint("##open", tr("a scene file (or drop one)"), ui.open_path, sizeof ui.open_path);
    ImGui::SameLine();
    if (ImGui::Button(tr("Open")) && ui.open_path[0]) requests.load = std::string(ui.open_path);
    ImGui::Checkbox(tr("springs"), &ui.view.springs);
    ImGui::SameLine();
    ImGui::Checkbox(tr("particles"), &ui.view.particles);
    ImGui::SameLine();
    ImGui::Checkbox(tr("surface"), &ui.view.surfaces);
    ImGui::Checkbox(tr("the limiting mode (M)"), &ui.view.mode);
    double strain = ui.view.strain_scale;
    if (slider(tr("strain scale"), strain, 1e-3, 0.5, true, "+-%.3f")) ui.view.strain_scale = strain;
    ImGui::Checkbox(tr("presentation (P)"), &ui.presentation);
    // The language, switched live (the fonts are remade before the next frame).
    const std::string now = current_language();
    const auto& all = app::languages();
    const auto shown = std::find_if(all.begin(), all.end(), [&](const app::Language& l) { return now == l.tag; });
    if (ImGui::BeginCombo(tr("language"), shown == all.end() ? now.c_str() : shown->name.c_str())) {
      for (const app::Language& l : all)
        if (ImGui::Selectable(l.name.c_str(), now == l.tag) && now != l.tag) requests.language = l.tag;
      ImGui::EndCombo();
    }
  }
}

// The controls' window: the pickers, the platform's own controls, the simulation's and the tools.
void controls_window(app::Session& session, UiState& ui, const FrameStats& stats, const PanelLayout& layout,
                     ImGuiWindowFlags docked, float s, bool few, Requests& requests) {
  const Rect& c = layout.controls;
  ImGui::SetNextWindowPos(ImVec2(c.x, c.y));
  ImGui::SetNextWindowSize(ImVec2(c.w, c.h));
  ImGui::Begin("springlab", nullptr, docked | ImGuiWindowFlags_NoTitleBar);
  ImGui::PushItemWidth(-std::min(130.0f * s, 0.4f * c.w));
  if (layout.touch) {  // the way back to the scene's room: close the sheet, fold the panel
    if (ImGui::Button(layout.kind == LayoutKind::Upright ? "\u2193" : "\u2190", ImVec2(ImGui::GetFrameHeight(), 0))) {
      if (layout.kind == LayoutKind::Upright) ui.sheet_open = false;
      else ui.side_open = false;
    }
    ImGui::SameLine();
  }
  pickers(ui, requests);
  if (ui.platform_controls) ui.platform_controls();
  about(session, s);
  ImGui::Separator();
  kind_panels(session.kind()).controls(session, ui, stats, layout, few);
  if (!few) tools(session, ui, stats, s, requests);
  ImGui::PopItemWidth();
  ImGui::End();
}

// The charts' window: side by side; one in presentation mode and in the upright layout (the
// lesson's first).
void charts_window(app::Session& session, const UiState& ui, const PanelLayout& layout, ImGuiWindowFlags docked) {
  const Rect& c = layout.charts;
  ImGui::SetNextWindowPos(ImVec2(c.x, c.y));
  ImGui::SetNextWindowSize(ImVec2(c.w, c.h));
  ImGui::Begin("Charts", nullptr, docked | ImGuiWindowFlags_NoTitleBar);
  std::vector<LessonChart> only = ui.lesson_charts;
  const bool one = layout.kind == LayoutKind::Upright || layout.kind == LayoutKind::Compact;
  if (one && only.size() > 1) only.erase(only.begin() + 1, only.end());
  kind_panels(session.kind()).charts(session, ImGui::GetContentRegionAvail().x, ImGui::GetContentRegionAvail().y,
                                     ui.presentation || one, only);
  ImGui::End();
}

// The stability region's window, over the scene's top left.
void region(app::Session& session, UiState& ui, const PanelLayout& layout, float s, int width, int height) {
  const float pad = 8.0f * s;
  if (layout.kind == LayoutKind::Wide) {
    region_window(session, ui, layout.charts.x, layout.controls.y, 0.55f * (width - layout.charts.x), 0.55f * height);
  } else {
    const float x = layout.scene.x + pad, y = layout.scene.y + pad;
    region_window(session, ui, x, y, std::max(0.55f * (width - x), std::min(480.0f * s, width - x - pad)),
                  std::max(0.55f * height, 0.5f * layout.scene.height));
  }
}

// Divergence in the single view: a banner, and the way out.
void divergence_window(app::Session& session, const UiState& ui, float s, int width, int height) {
  const float pad = 8.0f * s;
  const Simulation& first = session.primary().sim;
  if (const Divergence* trouble = first.trouble(); !session.comparing() && trouble) {
    // In a lesson, where diverging is often the point, one line at the foot of the scene (the
    // explanation on hover), never over the caption or what it describes.
    const bool lesson = ui.band > 0.0f;
    const draw::Viewport scene = scene_viewport(ui, width, height);
    if (lesson)
      ImGui::SetNextWindowPos(ImVec2(scene.x + 0.5f * scene.width, static_cast<float>(scene.y + scene.height) - pad),
                              ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    else
      ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.30f * height), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(lesson ? 0.0f : 560.0f * s, 0.0f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.05f, 0.05f, 0.95f));
    ImGui::Begin((tr("Diverged") + std::string("###diverged")).c_str(), nullptr, kPanel | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text(trouble->unstable ? tr("The simulation went numerically unstable at t = %.4g s")
                                  : tr("The simulation diverged at t = %.4g s"),
                trouble->t);
    if (lesson) {
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        text_wrapped(trouble->message(), {}, 520.0f * s);
        ImGui::EndTooltip();
      }
      ImGui::SameLine();
    } else {
      text_wrapped(trouble->message());  // the limit once analysed
    }
    if (ImGui::Button(tr("Reset (R)"))) session.reset();
    ImGui::End();
    ImGui::PopStyleColor();
  }
}

// A message (a file that failed to load), until dismissed.
void message_window(UiState& ui, float s, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.12f * height), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(600.0f * s, 0.0f));
  ImGui::Begin((tr("Message") + std::string("###message")).c_str(), nullptr, kPanel | ImGuiWindowFlags_AlwaysAutoResize);
  text_wrapped(ui.message, kNear, 600.0f * s - 2.0f * ImGui::GetStyle().WindowPadding.x);
  if (ImGui::Button(tr("OK"))) ui.message.clear();
  ImGui::End();
}

// The keys (F1).
void keys_window(UiState& ui, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.5f * height), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin((tr("Keys") + std::string("###keys")).c_str(), &ui.help, kPanel | ImGuiWindowFlags_AlwaysAutoResize);
  const char* keys[][2] = {{N_("space"), N_("pause or resume")}, {N_("S"), N_("one step")}, {N_("R"), N_("reset")},
                           {N_("1 - 9"), N_("choose a method")}, {N_("C"), N_("compare mode on or off")},
                           {N_("H"), N_("hide or show the panels")}, {N_("A"), N_("accuracy against cost: chart every method")},
                           {N_("G"), N_("the stability region, with the scene's modes")},
                           {N_("Y"), N_("your method: type a Butcher tableau, run it beside")},
                           {N_("M"), N_("show the mode that limits the step")},
                           {N_("P"), N_("presentation mode: larger, for a projector")},
                           {N_("\u2192  PgDn  N"), N_("lesson: the next step")},
                           {N_("\u2190  PgUp  B"), N_("lesson: the step before")},
                           {N_("F1"), N_("this help")},
                           {N_("F6  Ctrl+Tab"), N_("the keys into the panels, panel after panel")},
                           {N_("\u2190\u2191\u2192\u2193  space  Enter"), N_("in a panel: move, press, type a value")},
                           {N_("Esc  (in a panel)"), N_("the keys back to the scene")},
                           {N_("left drag"), N_("move a particle (release lets it go with its speed)")},
                           {N_("right drag"), N_("orbit the camera (3D) / pan (2D)")},
                           {N_("middle drag"), N_("pan")}, {N_("wheel"), N_("zoom")}, {N_("Esc"), N_("quit")}};
  if (ImGui::BeginTable("keys", 2)) {
    for (const auto& k : keys) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(kNeutral, "%s", tr(k[0]));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(tr(k[1]));
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace

Requests draw_panels(app::Session& session, UiState& ui, const FrameStats& stats, int width, int height) {
  Requests requests;
  ImGuiIO& io = ImGui::GetIO();
  const bool large = ui.presentation && io.Fonts->Fonts.Size > 1;
  if (large) ImGui::PushFont(io.Fonts->Fonts[1]);
  const float s = layout_scale(ui);
  const bool few = ui.presentation;
  const PanelLayout layout = panel_layout(ui, width, height);
  g_touch = layout.touch;
  // A thumb's targets: frames at least 44 units high (Apple's guideline; Material's is 48 dp).
  if (layout.touch) {
    const float frame_pad = std::max(ImGui::GetStyle().FramePadding.y, 0.5f * (44.0f * s - ImGui::GetFontSize()));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, frame_pad));
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 30.0f * s);
  }
  // The panels over the scene (a window too small to share): they keep their background.
  const bool over = layout.scene.x == 0 && layout.scene.width == width && !layout.controls.empty() &&
                    (layout.kind == LayoutKind::Wide || layout.kind == LayoutKind::Compact);
  const ImGuiWindowFlags docked = over || layout.touch ? kPanel : kDocked;

  if (ui.panels && !layout.strip.empty()) strip(session, ui, layout, s);
  if (ui.panels && !layout.controls.empty()) controls_window(session, ui, stats, layout, docked, s, few, requests);
  // (A lesson's accuracy chart takes the scene's and the charts' place: the charts are not drawn under it.)
  const bool covered = !ui.lesson.empty() && ui.accuracy;
  if (ui.panels && !layout.charts.empty() && !covered) charts_window(session, ui, layout, docked);
  if (ui.panels) region(session, ui, layout, s, width, height);
  divergence_window(session, ui, s, width, height);
  if (!ui.message.empty()) message_window(ui, s, width, height);
  if (ui.help) keys_window(ui, width, height);
  if (layout.touch) ImGui::PopStyleVar(2);
  if (large) ImGui::PopFont();
  return requests;
}

namespace {

// The charts the browser's words describe: energy, position and phase, and a free body's momentum.
std::vector<chart::Chart> mass_spring_charts_said(const app::Session& session) {
  std::vector<chart::Chart> out = {energy_chart(session), position_chart(session), phase_chart(session)};
  if (free_body(session.primary().sim.model())) out.push_back(momentum_chart(session));
  return out;
}

// C: the methods ticked (2 to 4), else the scene's own list, else the rows compared first.
std::vector<int> mass_spring_compare_choice(const app::Session& session, const UiState& ui) {
  const std::vector<Method> ticked = compare_methods(ui);
  if (ticked.size() < 2) return session.kind().compared_first();
  std::vector<int> rows;
  for (Method m : ticked) rows.push_back(static_cast<int>(m));
  return rows;
}

}  // namespace

const KindPanels& mass_spring_panels() {
  static const KindPanels panels{mass_spring_controls,     mass_spring_tools,          mass_spring_strip,
                                 mass_spring_charts,       mass_spring_charts_said,    mass_spring_compare_choice,
                                 mass_spring_caption,      mass_spring_progress};
  return panels;
}

std::vector<Counters> lane_counters(const app::Session& session) {
  std::vector<Counters> now;
  for (const app::Lane& lane : session.lanes()) now.push_back(lane.sim.counters());
  return now;
}

void count_frame(FrameStats& stats, const app::Session& session, const std::vector<Counters>& before) {
  stats.lanes.clear();
  stats.force_evals = stats.linear_solves = stats.solver_iterations = 0;
  for (std::size_t k = 0; k < session.lanes().size(); ++k) {
    const Counters& after = session.lanes()[k].sim.counters();
    Counters work;
    if (k < before.size()) {
      work.force_evals = after.force_evals - before[k].force_evals;
      work.linear_solves = after.linear_solves - before[k].linear_solves;
      work.solver_iterations = after.solver_iterations - before[k].solver_iterations;
    }
    stats.force_evals += work.force_evals;
    stats.linear_solves += work.linear_solves;
    stats.solver_iterations += work.solver_iterations;
    stats.lanes.push_back(work);
  }
}

}  // namespace springlab::ui
