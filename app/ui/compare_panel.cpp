#include "ui/compare_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "chart/compare_charts.hpp"
#include "chart/imgui_chart.hpp"
#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"
#include "springlab/text.hpp"

namespace springlab::ui {

SweepSettings ComparePanel::settings(const app::Session& session) const {
  SweepSettings s;
  for (const MethodInfo& m : springlab::methods())
    if (methods.has(m.id)) s.methods.push_back(m.id);
  const Simulation& sim = session.primary().sim;
  const double dt = sim.settings().dt;
  s.h_max = 2 * dt;
  s.h_min = 2 * dt / step_range;
  s.points = points;
  s.duration = std::max(static_cast<double>(duration), s.h_max);
  s.tol_min = 1e-9;
  s.tol_max = 1e-4;
  s.step = sim.settings().step;
  s.drift_h = dt;
  s.drift_duration = std::max(static_cast<double>(duration), dt) * 4;
  return s;
}

void ComparePanel::start(const app::Session& session) {
  const Simulation& sim = session.primary().sim;
  sweep.start(sim.model(), sim.state(), settings(session));
}

namespace {

// (A phone's panel is narrower than the row of sliders, buttons and tabs a laptop's holds: they
// wrap, same_line_if_fits.)
float labelled_width(float frame,
                     const char* label) {  // a slider's or a radio button's, with its label
  return frame + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}
float button_width(const char* label) {
  return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

// The methods to sweep, ticked in their colours: none ticked means all. Five columns; where the
// longest name does not fit five (a phone), as many as it fits, folded under a header until
// opened: unfolded they would take the chart's room, and the chart is what the step is about.
void compare_method_ticks(ComparePanel& panel) {
  float name = 0.0f;
  int ticked = 0;
  for (const MethodInfo& m : methods()) {
    name = std::max(name, ImGui::CalcTextSize(m.name).x);
    ticked += panel.methods.has(m.id) ? 1 : 0;
  }
  const float column = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + name +
                       ImGui::GetStyle().CellPadding.x * 2;
  const int columns = std::clamp(static_cast<int>(ImGui::GetContentRegionAvail().x / column), 2, 5);
  const bool shown =
      columns == 5 ||
      ImGui::CollapsingHeader(
          (format_text(tr("Methods (%d)"), ticked) + std::string("###methods")).c_str());
  if (shown && ImGui::BeginTable("methods", columns)) {
    for (const MethodInfo& m : methods()) {
      ImGui::TableNextColumn();
      const draw::Rgba c = draw::method_color(m.id);
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(c.r, c.g, c.b, 1));
      bool on = panel.methods.has(m.id);
      if (ImGui::Checkbox(m.name, &on)) panel.methods.set(m.id, on);
      ImGui::PopStyleColor();
    }
    ImGui::EndTable();
  }
}

}  // namespace

void draw_compare_panel(ComparePanel& panel, const app::Session& session, float scale,
                        const Rect& place, int width, int height) {
  if (!panel.open) return;
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;
  if (place.empty()) {
    ImGui::SetNextWindowPos(ImVec2(380.0f * scale, 20.0f * scale), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(width - 400.0f * scale, 0.62f * height), ImGuiCond_Appearing);
  } else {  // (what it covers, the charts or a lane, does not show through)
    ImGui::SetNextWindowPos(ImVec2(place.x, place.y));
    ImGui::SetNextWindowSize(ImVec2(place.w, place.h));
    ImGui::SetNextWindowBgAlpha(1.0f);
    flags |= ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize;
  }
  if (!ImGui::Begin((tr("Accuracy against cost") + std::string("###accuracy")).c_str(), &panel.open,
                    flags)) {
    ImGui::End();
    return;
  }
  const bool running = panel.sweep.running();
  const auto [done, total] = panel.sweep.progress();
  const float slider = 110.0f * scale;
  ImGui::PushItemWidth(slider);
  ImGui::SliderInt(tr("steps"), &panel.points, 3, 10);
  same_line_if_fits(labelled_width(slider, tr("seconds")));
  ImGui::SliderFloat(tr("seconds"), &panel.duration, 0.2f, 5.0f, "%.1f");
  same_line_if_fits(labelled_width(slider, tr("range")));
  ImGui::SliderFloat(tr("range"), &panel.step_range, 4.0f, 64.0f, tr("dt/%.0f..2dt"),
                     ImGuiSliderFlags_Logarithmic);
  ImGui::PopItemWidth();
  same_line_if_fits(button_width(running ? tr("Cancel") : tr("Run")));
  if (!running && ImGui::Button(tr("Run"))) panel.start(session);
  if (running && ImGui::Button(tr("Cancel"))) panel.sweep.cancel();
  if (running || done > 0) {
    same_line_if_fits(160.0f * scale);
    ImGui::ProgressBar(total > 0 ? static_cast<float>(done) / total : 0.0f,
                       ImVec2(160.0f * scale, 0),
                       (std::to_string(done) + " / " + std::to_string(total)).c_str());
  }
  compare_method_ticks(panel);

  const SweepResult result = panel.sweep.snapshot();
  if (result.runs.empty()) {
    ImGui::TextDisabled(
        tr("Run: every method over steps from dt/%.0f to 2 dt (adaptive ones over tolerances), "
           "each against the exact solution or a fine RK4 run."),
        panel.step_range);
  } else {
    const auto charts = chart::compare_charts(result, session.scene().name);
    // A tab a chart, in compare_charts' order (energy drift and the iterative rows' solver error
    // only where the sweep made them).
    const auto tab = [](const std::string& name) {
      // The charts' keys (not shown) and their tabs' names.
      static const std::pair<const char*, const char*> kTabs[] = {
          {"work-precision", N_("error vs time")},       // not shown: the key
          {"work-precision-work", N_("error vs work")},  // not shown: the key
          {"convergence", N_("convergence")},            // not shown: the key
          {"stability", N_("stability")},                // not shown: the key
          {"energy-drift", N_("energy drift")},          // not shown: the key
          {"solver-convergence", N_("solver error")}};   // not shown: the key
      for (const auto& [key, text] : kTabs)
        if (name == key) return tr(text);
      return tr(name.c_str());
    };
    for (int k = 0; k < static_cast<int>(charts.size()); ++k) {
      if (k > 0) same_line_if_fits(labelled_width(ImGui::GetFrameHeight(), tab(charts[k].name)));
      if (ImGui::RadioButton(tab(charts[k].name), panel.chart == k)) panel.chart = k;
    }
    if (running && panel.chart >= 3) ImGui::TextDisabled(tr("(measured at the end of the sweep)"));
    const int k = std::min(panel.chart, static_cast<int>(charts.size()) - 1);
    chart::chart_widget("##sweep", charts[k].chart, ImGui::GetContentRegionAvail());
  }
  ImGui::End();
}

}  // namespace springlab::ui
