// The inverse-kinematics kind's UI half (kind_panels.hpp): the solver and its iterations a frame,
// each lane's progress and what it means, the chart of each solver's distance to the target, and
// the caption's and legend's words.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "chart/imgui_chart.hpp"
#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"
#include "session/ik_kind.hpp"
#include "springlab/text.hpp"
#include "ui/kind_panels.hpp"
#include "ui/live_charts.hpp"
#include "ui/theme.hpp"
#include "ui/widgets.hpp"

namespace springlab::ui {

namespace {

const app::IkKind& ik_kind(const app::Session& session) {
  return dynamic_cast<const app::IkKind&>(session.kind());
}

// How far each solver's end is from the target, frame by frame (log scale: the solvers converge
// at very different rates, and a stuck one levels off).
chart::Chart error_chart(const app::Session& session) {
  chart::Chart error;
  error.title =
      tr("Distance from the end to the target, against time (drag the target to start again)");
  error.x.label = "t (s)";
  error.y.label = "m";
  error.y.log = true;
  for (const app::Lane& lane : session.lanes()) {
    chart::Series s = series(app::lane_name(lane), draw::lane_color(lane), lane.history.t,
                             app::ik_lane(lane).error);
    for (double& y : s.y)
      y = std::max(y, 1e-9);  // a log axis needs > 0: an exact hit shows at 1e-9
    error.series.push_back(std::move(s));
  }
  return error;
}

void charts(app::Session& session, float width, float height, bool,
            const std::vector<LessonChart>&) {
  chart::chart_widget("##ik", error_chart(session), ImVec2(width, height));
}

std::vector<chart::Chart> charts_said(const app::Session& session) {
  return {error_chart(session)};
}

// The solver, side by side or not, iterations a frame, and each lane's progress, with the two
// difficulties spelt out: no solution, or many.
void controls(app::Session& session, UiState&, const FrameStats& stats, const PanelLayout&, bool) {
  app::IkKind& kind = dynamic_cast<app::IkKind&>(session.kind());
  const IkScene& ik = kind.scene();
  row_picker(session, tr("solver"), true);
  if (ImGui::Button(session.comparing() ? tr("One solver (C)") : tr("Solvers side by side (C)")))
    session.set_compare_rows(session.comparing() ? std::vector<int>{} : kind.compared_first());
  int per_frame = kind.iterations_per_frame();
  if (ImGui::SliderInt(tr("iterations/frame"), &per_frame, 1, 100, "%d",
                       ImGuiSliderFlags_Logarithmic))
    kind.set_iterations_per_frame(per_frame);
  ImGui::TextDisabled(tr("reach %.3g m, %d links; tolerance %.2g m"), ik.chain.reach(),
                      ik.chain.size(), ik.settings.tolerance);
  for (const app::Lane& lane : session.lanes()) {
    const app::IkLane& l = app::ik_lane(lane);
    ImGui::PushStyleColor(ImGuiCol_Text, v4(draw::lane_color(lane)));
    ImGui::Text("%s", app::lane_name(lane).c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    const char* state = l.status.converged ? tr("reached")
                        : l.status.stalled ? tr("stuck")
                                           : tr("iterating");
    ImGui::Text(tr("%s in %d, error %.2g m"), state, l.status.iterations, l.status.error);
  }
  const IkStatus& first = app::ik_lane(session.primary()).status;
  if (!first.reachable)
    text_wrapped(tr("The target is out of reach: no pose puts the end on it. The chain stretches "
                    "straight towards it, as close as it can get."),
                 v4(kNearText));
  else if (session.comparing())
    text_wrapped_disabled(
        tr("One target, several poses: each solver, from the same start, settles on its own "
           "answer. Inverse kinematics has many solutions, or none."));
  else
    text_wrapped_disabled(tr("Drag the red target. Press C to see the solvers side by side."));
  transport(session);
  clocks(session, stats);
}

void tools(app::Session&, UiState&, float) {}  // (no studies: the solvers' chart is the study)

void strip(app::Session& session, UiState&, float) {
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
  row_picker(session, "##solver", false);
}

std::vector<int> compare_choice(const app::Session& session, const UiState&) {
  return ik_kind(session).compared_first();
}

std::string caption(const app::Session& session, const std::string& scene_name,
                    const std::string&) {
  char s[320];
  const app::IkLane& ik = app::ik_lane(session.primary());
  std::snprintf(s, sizeof s, tr("%s  |  %s  |  iteration %d, error %.3g m%s"), scene_name.c_str(),
                app::lane_label(session.primary()).c_str(), ik.status.iterations, ik.status.error,
                ik.status.reachable ? "" : tr("  |  target out of reach"));
  return s;
}

std::string progress(const app::Lane& lane) {
  const app::IkLane& ik = app::ik_lane(lane);
  char s[96];
  std::snprintf(s, sizeof s, tr("  %d it., error %.2g m%s"), ik.status.iterations, ik.status.error,
                ik.status.converged ? ""
                : ik.status.stalled ? tr(" (stuck)")
                                    : "");
  return s;
}

}  // namespace

const KindPanels& ik_panels() {
  static const KindPanels panels{controls,    tools,          strip,   charts,
                                 charts_said, compare_choice, caption, progress};
  return panels;
}

}  // namespace springlab::ui
