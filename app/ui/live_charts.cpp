#include "ui/live_charts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "draw/marks.hpp"
#include "draw/palette.hpp"
#include "session/mass_spring_kind.hpp"
#include "springlab/momentum.hpp"
#include "springlab/text.hpp"

namespace springlab::ui {

namespace {

// A lane that diverged: its line does not set the chart's scale, leaves it with a marker on the
// edge, and its legend entry (red: the chart's legend colours an escaping series so) gives the
// value it reached. When it diverged is said beside the lane and in the clocks; kept short here,
// a legend never wraps over the lines it names.
void mark_diverged(chart::Series& s, const app::Lane& lane, const char* unit) {
  if (!lane.sim.diverged()) return;
  s.escapes = true;
  if (s.label.empty() || s.y.empty()) return;
  s.label += format_text(" %.2g ", s.y.back()) + unit;
}

const char* const kAxes = "xyz";  // not shown: the axes' letters

}  // namespace

chart::Series series(const std::string& label, const draw::Rgba& color, const app::Series& x,
                     const app::Series& y, bool dashed) {
  chart::Series s;
  s.label = label;
  s.color = color;
  s.dashed = dashed;
  const std::size_t n = std::min(x.size(), y.size());
  s.x.resize(n);
  s.y.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    s.x[k] = x[x.size() - n + k];
    s.y[k] = y[y.size() - n + k];
  }
  return s;
}

chart::Chart energy_chart(const app::Session& session) {
  const bool compare = session.comparing();
  const draw::Rgba white{0.95f, 0.95f, 0.95f, 1}, ke{1.0f, 0.55f, 0.25f, 1},
      pe{0.45f, 0.7f, 1.0f, 1}, lost{0.7f, 0.7f, 0.7f, 1};
  chart::Chart energy;
  energy.title = tr("Energy");
  energy.x.label = "t (s)";
  energy.y.label = "J";
  energy.end_labels = true;
  for (const app::Lane& lane : session.lanes()) {
    const app::History& h = lane.history;
    const draw::Rgba c = draw::lane_color(lane);
    const std::string name = app::lane_name(lane);
    if (!compare) {
      energy.series.push_back(series(tr("kinetic"), ke, h.t, h.kinetic));
      energy.series.push_back(series(tr("potential"), pe, h.t, h.potential));
      energy.series.push_back(series(tr("total"), white, h.t, h.total));
    } else {
      energy.series.push_back(series(name, c, h.t, h.total));
      energy.series.back().mark = draw::lane_mark(lane);
    }
    // Total plus what damping, drag and friction took: flat unless the method itself drifts. Not
    // for a step of one's own, whose damping is its own, not the scene's that this counts.
    const bool counted = lane.own.empty();
    if (counted) {
      chart::Series kept =
          series(compare ? "" : tr("total + lost"), compare ? c : lost, h.t, h.total, true);
      for (std::size_t k = 0; k < kept.y.size(); ++k)
        kept.y[k] += h.dissipated[h.dissipated.size() - kept.y.size() + k];
      energy.series.push_back(kept);
    }
    const std::size_t from = energy.series.size() - (compare ? 1 : 3) - (counted ? 1 : 0);
    for (std::size_t k = from; k < energy.series.size(); ++k)
      mark_diverged(energy.series[k], lane, "J");
  }
  return energy;
}

chart::Chart position_chart(const app::Session& session) {
  const int a = session.watched_axis();
  chart::Chart position;
  position.title = format_text(tr("Particle %d, %c(t)"), session.watched(), kAxes[a]);
  position.x.label = "t (s)";
  position.y.label = std::string(1, kAxes[a]) + " (m)";
  position.end_labels = true;
  for (const app::Lane& lane : session.lanes()) {
    position.series.push_back(
        series(app::lane_name(lane), draw::lane_color(lane), lane.history.t, lane.history.x));
    position.series.back().mark = draw::lane_mark(lane);
    mark_diverged(position.series.back(), lane, "m");
  }
  if (session.primary().history.exact_x.size() > 0)
    position.series.push_back(series(tr("exact"), draw::Rgba{0.95f, 0.95f, 0.95f, 1},
                                     session.primary().history.t, session.primary().history.exact_x,
                                     true));
  return position;
}

chart::Chart phase_chart(const app::Session& session) {
  chart::Chart phase;
  phase.title = tr("Phase");
  phase.x.label = std::string(1, kAxes[session.watched_axis()]) + " (m)";
  phase.y.label = "v (m/s)";
  phase.legend = false;
  for (const app::Lane& lane : session.lanes()) {
    chart::Series s = series("", draw::lane_color(lane), lane.history.x, lane.history.v);
    // A lane that diverged or is blowing up: its path up to its last sane state, as its scene
    // draws it (the blow-up would set the scale and leave the rest a dot).
    if (lane.wild() && lane.history.t.size() >= s.x.size()) {
      const app::Series& t = lane.history.t;
      std::size_t keep = 0;
      for (std::size_t k = 0; k < s.x.size(); ++k)
        if (t[t.size() - s.x.size() + k] <= lane.sane.t + 1e-12) keep = k + 1;
      s.x.resize(keep);
      s.y.resize(keep);
    }
    phase.series.push_back(std::move(s));
    phase.series.back().mark = draw::lane_mark(lane);
  }
  return phase;
}

// Adaptive lanes: the internal step their controller chose, frame by frame (log scale), and a
// cross on each frame in which it threw tries away.
chart::Chart steps_chart(const app::Session& session) {
  chart::Chart steps;
  steps.title = tr("The adaptive step: accepted (line), frames with rejected tries (x)");
  steps.x.label = "t (s)";
  steps.y.label = tr("internal step (s)");
  steps.y.log = true;
  for (const app::Lane& lane : session.lanes()) {
    if (!method_info(lane.sim.settings().method).adaptive()) continue;
    const app::History& h = lane.history;
    chart::Series step =
        series(format_text(tr("%s step"), method_info(lane.sim.settings().method).name),
               draw::method_color(lane.sim.settings().method), h.t, h.step);
    step.mark = draw::method_mark(lane.sim.settings().method);
    chart::Series rejected;
    rejected.label = tr("rejected");
    rejected.color = draw::kDiverged;
    for (std::size_t k = 1; k < step.x.size(); ++k) {
      const std::size_t i = h.rejected.size() - step.x.size() + k;
      if (h.rejected[i] > h.rejected[i - 1] && step.y[k] > 0.0) {
        rejected.x.push_back(step.x[k]);
        rejected.y.push_back(step.y[k]);
        rejected.crossed.push_back(true);
      }
    }
    for (double& y : step.y)
      y = y > 0.0 ? y : std::numeric_limits<double>::quiet_NaN();  // before the first step
    steps.series.push_back(std::move(step));
    if (!rejected.x.empty()) steps.series.push_back(std::move(rejected));
  }
  return steps;
}

// A free body's constants of the motion, lane by lane (momentum.hpp): the change of P (solid) and
// of L (dashed) since it became free, against their scales, on a log scale from rounding
// (1e-16, where an exact method's lines lie) to all of it. A lane that keeps them lies at the
// bottom; kMomentumVisible (1e-3), where a change shows, is a dashed grey line.
chart::Chart momentum_chart(const app::Session& session) {
  constexpr double kRounding = 1e-16;
  chart::Chart chart;
  chart.title = tr("Momentum: change of P (solid) and L (dashed)");
  chart.x.label = "t (s)";
  chart.y.label = tr("|P - P0|, |L - L0| since free, of their scale");
  chart.y.log = true;
  chart.end_labels = true;
  bool any = false;
  for (const app::Lane& lane : session.lanes()) {
    const app::MassSpringLane* part = app::mass_spring_lane(lane);  // (the kind's series)
    if (!part) continue;
    for (const bool angular : {false, true}) {
      chart::Series s =
          series(angular ? "" : app::lane_name(lane), draw::lane_color(lane), lane.history.t,
                 angular ? part->angular_change : part->linear_change, angular);
      for (double& y : s.y) y = std::isnan(y) ? y : std::max(y, kRounding);
      any = any || std::any_of(s.y.begin(), s.y.end(), [](double y) { return !std::isnan(y); });
      s.mark = draw::lane_mark(lane);
      chart.series.push_back(std::move(s));
    }
  }
  if (!any) {
    chart.series.clear();
    chart.title =
        free_body(session.primary().sim.model())
            ? tr("Momentum: a free body at rest (its P0 is taken once it moves)")
            : tr("Momentum: not a free body here (pins, gravity, drag or colliders act on it)");
    return chart;
  }
  chart::Series visible;
  visible.color = draw::Rgba{0.6f, 0.6f, 0.6f, 1};
  visible.dashed = true;
  visible.x = {chart.series.front().x.empty() ? 0.0 : chart.series.front().x.front(),
               chart.series.front().x.empty() ? 1.0 : chart.series.front().x.back()};
  visible.y = {kMomentumVisible, kMomentumVisible};
  visible.label = tr("visible (1e-3)");
  chart.series.push_back(std::move(visible));
  return chart;
}

}  // namespace springlab::ui
