#include "ui/widgets.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "chart/imgui_chart.hpp"
#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"
#include "springlab/text.hpp"
#include "ui/live_charts.hpp"
#include "ui/overlay.hpp"

namespace springlab::ui {

// On a touch layout, - and + beside the slider, so that a thumb sets a value a step at a
// time (a logarithmic slider by x1.25, a linear one by a twentieth of its range).
bool slider(const char* label, double& value, double lo, double hi, bool log, bool touch,
            const char* format) {
  const ImGuiSliderFlags flags = log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
  float v = static_cast<float>(value);
  if (!touch) {
    const bool changed = ImGui::SliderFloat(label, &v, static_cast<float>(lo),
                                            static_cast<float>(hi), format, flags);
    if (changed) value = v;
    return changed;
  }
  const std::string_view name(label);
  const std::string shown(name.substr(0, name.find("##")));
  const float button = ImGui::GetFrameHeight(), spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  const float width = ImGui::CalcItemWidth() - 2 * (button + spacing);
  ImGui::PushID(label);
  double next = value;
  if (ImGui::Button("-", ImVec2(button, button)))
    next = log ? value / 1.25 : value - (hi - lo) / 20;
  ImGui::SameLine(0, spacing);
  ImGui::SetNextItemWidth(std::max(width, button));
  if (ImGui::SliderFloat("##value", &v, static_cast<float>(lo), static_cast<float>(hi), format,
                         flags))
    next = v;
  ImGui::SameLine(0, spacing);
  if (ImGui::Button("+", ImVec2(button, button)))
    next = log ? std::max(value, lo > 0 ? lo : 1e-3 * hi) * 1.25 : value + (hi - lo) / 20;
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

void widest_beside(const char* label) {
  const std::string_view shown =
      std::string_view(label).substr(0, std::string_view(label).find("##"));
  if (shown.empty()) return;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemInnerSpacing.x -
                          ImGui::CalcTextSize(shown.data(), shown.data() + shown.size()).x);
}

void row_picker(app::Session& session, const char* label, bool coloured) {
  if (session.comparing()) return;
  const app::SceneKind& kind = session.kind();
  widest_beside(label);
  // Its label, or where that does not fit the box (a small laptop's panel), its short name
  // ("heun-wrong" for "Heun, one entry wrong"), never a label cut.
  const float room =
      ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2.0f * ImGui::GetStyle().FramePadding.x;
  std::string preview = app::lane_label(session.primary());
  if (ImGui::CalcTextSize(preview.c_str()).x > room)
    preview = std::string(app::lane_row(session.primary()).name);
  if (!ImGui::BeginCombo(label, preview.c_str())) return;
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
  const auto width = [](const char* label) {
    return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x;
  };
  if (ImGui::Button(session.paused() ? tr("Resume (space)") : tr("Pause (space)")))
    session.set_paused(!session.paused());
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

// Charts side by side over the room left in the window.
void charts_row(const std::vector<chart::Chart>& shown, float width, float height) {
  const float w = (width - (shown.size() - 1) * ImGui::GetStyle().ItemSpacing.x) /
                  std::max<std::size_t>(1, shown.size());
  for (std::size_t k = 0; k < shown.size(); ++k) {
    if (k > 0) ImGui::SameLine();
    chart::chart_widget(("##chart" + std::to_string(k)).c_str(), shown[k], ImVec2(w, height));
  }
}

}  // namespace springlab::ui
