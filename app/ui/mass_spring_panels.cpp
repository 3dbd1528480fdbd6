#include "ui/mass_spring_panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "chart/imgui_chart.hpp"
#include "chart/stability_region.hpp"
#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"
#include "springlab/text.hpp"
#include "ui/gauge_verdict.hpp"
#include "ui/kind_panels.hpp"
#include "ui/live_charts.hpp"
#include "ui/overlay.hpp"
#include "ui/physics_controls.hpp"
#include "ui/widgets.hpp"

namespace springlab::ui {

namespace {

// The analysis a lane shows: the latest (in the background mode it may be of the scene a moment
// ago, while the next is made); made here if the session makes them where needed.
const StabilityAnalysis* shown_analysis(app::Session& session, app::Lane& lane) {
  if (lane.analysis) return lane.analysis.get();
  if (!session.background_analysis()) return &lane.sim.stability();
  return nullptr;
}

// The stability gauge of one lane: h against the method's limit on one row (the verdict on the
// next when it is long), and with `explain` the limit and the mode that sets it (and on a touch
// layout, with no hover, what the tooltip says).
void gauge(app::Session& session, app::Lane& lane, float width, bool explain, bool touch) {
  const Simulation& sim = lane.sim;
  const MethodInfo& m = method_info(sim.settings().method);
  const StabilityAnalysis* analysis = shown_analysis(session, lane);
  const StabilityLimit* limit = analysis ? &analysis->limit(m.id) : nullptr;
  const GaugeVerdict said = gauge_verdict(lane, analysis, explain);
  const double fraction = said.fraction;
  const std::string& verdict = said.text;
  const std::string& momentum_line = said.momentum;
  const ImVec4 color = said.tone == Tone::Safe     ? kSafe
                       : said.tone == Tone::Near   ? kNear
                       : said.tone == Tone::Beyond ? kBeyond
                                                   : kNeutral;
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
  dl->AddRectFilled(q, ImVec2(q.x + bar_w, q.y + bar_h), ImGui::GetColorU32(ImGuiCol_FrameBg),
                    3.0f);
  dl->AddRectFilled(q, ImVec2(q.x + bar_w * static_cast<float>(fraction), q.y + bar_h),
                    ImGui::GetColorU32(color), 3.0f);
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
  if (touch) text_wrapped_disabled(tr(m.stability));  // (no hover under a finger)
  if (!momentum_line.empty()) text_wrapped_disabled(momentum_line);
  if (analysis && !analysis->oscillates()) {
    text_wrapped_disabled(format_text(tr("no oscillating modes (%s); %s"),
                                      tr(analysis->no_modes_reason()).c_str(),
                                      describe(*limit).c_str()));
  } else if (limit->mode && std::isfinite(limit->h) && limit->h > 0.0) {
    char mode[96];
    std::snprintf(mode, sizeof mode, tr(" (its mode: %.4g rad/s, damping ratio %.2g)"),
                  limit->mode->w, limit->mode->damping_ratio());
    text_wrapped_disabled(describe(*limit) + mode);
  } else {
    text_wrapped_disabled(describe(*limit));
  }
}

}  // namespace

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

namespace {

// The charts: energy, the watched particle's position (with the exact solution) and its phase
// plot side by side; one (energy) in presentation mode; in a lesson, the ones its step shows.
// For a class (presentation, lessons) the lines are thicker; the stability regions keep theirs.
void mass_spring_charts(app::Session& session, float width, float height, bool presentation,
                        const std::vector<LessonChart>& only) {
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

// The sliders of the physics; `presenting`: only dt, k_s and k_d (presentation mode).
void parameters(app::Session& session, UiState& ui, bool touch, bool presenting) {
  Simulation& sim = session.lanes()[0].sim;
  double mu = session.friction();
  double tol = sim.settings().step.tolerance;
  const std::vector<PhysicsControl> controls = physics_controls(session, ui);
  // k_s, k_d and dt, then the sub-steps, then the rest (not in presentation mode).
  const auto draw = [&](const PhysicsControl& c) {
    double v = c.value;
    if (slider(c.label.c_str(), v, c.lo, c.hi, c.log, touch, c.format)) c.set(session, v);
  };
  std::size_t next = 0;
  for (; next < controls.size() && std::string_view(controls[next].id) != "mass"; ++next)
    draw(controls[next]);
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
  ImGui::PushItemWidth(ImGui::CalcItemWidth() - ImGui::CalcTextSize(tr("auto")).x -
                       ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().ItemInnerSpacing.x);
  if (ImGui::SliderInt("##substeps", &substeps, 1, 256, shown.c_str(),
                       ImGuiSliderFlags_Logarithmic))
    session.set_substeps(substeps);
  ImGui::PopItemWidth();
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  bool automatic = session.auto_substeps();
  if (ImGui::Checkbox(tr("auto"), &automatic)) {
    if (automatic)
      session.set_auto_substeps();
    else
      session.set_substeps(sim.settings().substeps);
  }
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::TextUnformatted(tr("sub-steps"));
  for (const app::Lane& lane : session.lanes())
    if (lane.sim.auto_substeps() && lane.sim.substeps_capped() && lane.analysis) {
      const bool hopeless = lane.analysis->limit(lane.sim.settings().method).h == 0.0;
      text_wrapped(app::lane_name(lane) + ": " +
                       (hopeless ? tr("unstable at any step: sub-steps cannot help")
                                 : tr("sub-steps capped: still past its limit")),
                   kNear);
      break;
    }
  if (presenting) return;
  for (; next < controls.size(); ++next) draw(controls[next]);
  if (sim.model().has_colliders() && slider(tr("friction"), mu, 0.0, 2.0, false, touch, "%.2f"))
    session.set_friction(mu);
  if (method_info(session.method()).adaptive() &&
      slider(tr("tolerance"), tol, 1e-10, 1e-1, true, touch, "%.1e"))
    session.set_tolerance(tol);
  if (method_info(session.method()).family == MethodFamily::Iterative) {
    // Iterations a step: the solver error against the cost (XPBD: passes over the springs).
    int iterations = iterations_for(session.method(), sim.settings().step);
    if (ImGui::SliderInt(tr("iterations"), &iterations, 1, 100, "%d", ImGuiSliderFlags_Logarithmic))
      session.set_iterations(std::clamp(iterations, 1, 10000));
  }
  int speed_exp = static_cast<int>(std::lround(std::log2(session.speed())));
  const char* speeds[] = {"1/16", "1/8", "1/4", "1/2", "1", "2", "4"};
  if (ImGui::SliderInt(tr("speed"), &speed_exp, -4, 2, speeds[speed_exp + 4]))
    session.set_speed(std::pow(2.0, speed_exp));
}

// The mass-spring kind's strip tail: the method and dt (the strip is the touch layouts' own).
void mass_spring_strip(app::Session& session, UiState& ui, float button) {
  ImGui::SameLine();
  // The method's combo takes what the dt slider leaves: at least its two buttons and room for
  // its value's text (a phone's row: they ran off its right edge; then "dt 0.0" was cut).
  const float left = ImGui::GetContentRegionAvail().x;
  double dt = session.primary().sim.settings().dt;
  char shown[32];
  std::snprintf(shown, sizeof shown, "dt %.3g", dt);  // symbols
  const ImGuiStyle& style = ImGui::GetStyle();
  const float dt_least = 2.0f * button + ImGui::CalcTextSize(shown).x +
                         2.0f * style.FramePadding.x + 2.0f * style.ItemInnerSpacing.x +
                         style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(button, std::min(0.45f * left, left - dt_least)));
  row_picker(session, "##method", false);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
  // (Its value alone where "dt" and the value would not fit between the - and + buttons.)
  const float inside = ImGui::GetContentRegionAvail().x -
                       2.0f * (button + style.ItemInnerSpacing.x) - 2.0f * style.FramePadding.x;
  const char* format = ImGui::CalcTextSize(shown).x <= inside ? "dt %.3g" : "%.3g";  // symbols
  if (slider("##dt", dt, ui.ranges.dt / 100, std::min(1.0, std::max(0.1, ui.ranges.dt * 100)), true,
             true, format))
    session.set_dt(dt);
}

// The mass-spring kind's controls: the method, play and step, the clocks, each lane's stability
// gauge and the parameters.
void mass_spring_controls(app::Session& session, UiState& ui, const FrameStats& stats,
                          const PanelLayout& layout, bool presenting) {
  row_picker(session, tr("method"), true);
  transport(session);
  clocks(session, stats);
  // Stability: the gauge of each lane, under the method it judges.
  const float inner_w =
      layout.controls.w - 2 * ImGui::GetStyle().WindowPadding.x - ImGui::GetStyle().ScrollbarSize;
  for (app::Lane& lane : session.lanes())
    gauge(session, lane, inner_w, !session.comparing(), layout.touch);
  ImGui::Separator();
  parameters(session, ui, layout.touch, presenting);
}

// The methods ticked to compare, as the kind's rows (row k is Method k).
std::vector<int> ticked_rows(const UiState& ui) {
  std::vector<int> rows;
  for (Method m : compare_methods(ui)) rows.push_back(static_cast<int>(m));
  return rows;
}

// The mass-spring kind's tools: the accuracy, region and tableau panels' buttons and the compare
// choices.
void mass_spring_tools(app::Session& session, UiState& ui, float scale) {
  if (ImGui::Button(ui.accuracy ? tr("Hide accuracy (A)") : tr("Accuracy vs cost (A)")))
    ui.accuracy = !ui.accuracy;
  ImGui::SameLine();
  if (ImGui::Button(ui.region ? tr("Hide region (G)") : tr("Stability region (G)")))
    ui.region = !ui.region;
  if (ImGui::Button(ui.tableau ? tr("Hide your method (Y)") : tr("Your method (Y)")))
    ui.tableau = !ui.tableau;
  if (ImGui::CollapsingHeader(tr("Compare methods"))) {
    if (ImGui::Button(session.comparing() ? tr("Single view (C)") : tr("Compare (C)"))) {
      if (session.comparing())
        session.set_compare_rows({});
      else if (ticked_rows(ui).size() >= 2)
        session.set_compare_rows(ticked_rows(ui));
    }
    ImGui::SameLine();
    ImGui::TextDisabled(tr("tick 2 to 4:"));
    if (ImGui::BeginTable("compare", 2)) {
      for (const MethodInfo& m : methods()) {
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, v4(draw::method_color(m.id)));
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(3 * scale, 1 * scale));
        bool on = ui.compare_choice.has(m.id);
        if (ImGui::Checkbox(m.name, &on)) ui.compare_choice.set(m.id, on);
        ImGui::PopStyleVar();
        ImGui::PopStyleColor();
      }
      ImGui::EndTable();
    }
  }
}

// The charts the browser's words describe: energy, position and phase, and a free body's momentum.
std::vector<chart::Chart> mass_spring_charts_said(const app::Session& session) {
  std::vector<chart::Chart> out = {energy_chart(session), position_chart(session),
                                   phase_chart(session)};
  if (free_body(session.primary().sim.model())) out.push_back(momentum_chart(session));
  return out;
}

// C: the methods ticked (2 to 4), else the scene's own list, else the rows compared first.
std::vector<int> mass_spring_compare_choice(const app::Session& session, const UiState& ui) {
  const std::vector<int> ticked = ticked_rows(ui);
  return ticked.size() < 2 ? session.kind().compared_first() : ticked;
}

}  // namespace

const KindPanels& mass_spring_panels() {
  static const KindPanels panels{mass_spring_controls,    mass_spring_tools,
                                 mass_spring_strip,       mass_spring_charts,
                                 mass_spring_charts_said, mass_spring_compare_choice,
                                 mass_spring_caption,     mass_spring_progress};
  return panels;
}

}  // namespace springlab::ui
