#include "ui/gauge_verdict.hpp"

#include <algorithm>
#include <cmath>

#include "session/mass_spring_kind.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/momentum.hpp"
#include "springlab/text.hpp"

namespace springlab::ui {

namespace {

// An iterative row, always stable, pays instead: at rest in softness, its stretch against the
// spring model's under the same load (it acts as k_s x rest_stretch / rms_stretch); in motion in
// damping, the energy it takes out beyond the physics' damping over the last second (the last 61
// samples: -(d net + d dissipated) / dt) (iterative_cost.hpp). Says it in out.text, out.tone Near
// where it is much softer or puts energy in.
void iterative_row_verdict(const app::Lane& lane, const StabilityAnalysis& analysis,
                           GaugeVerdict& out) {
  const Simulation& sim = lane.sim;
  Tone& color = out.tone;
  std::string& verdict = out.text;
  const app::History& hist = lane.history;
  const std::size_t n = hist.t.size(), back = std::min<std::size_t>(n, 61);
  // Each only where it is defined: the stiffness it acts as where the springs carry a load to
  // pins, the energy it takes where no collider's contacts take any (iterative_cost.hpp).
  const bool resting = at_rest(sim.model(), sim.state(), sim.energy_scale());
  if (resting && loaded_balance(sim.model()) && analysis.rest_stretch() > 0.0) {
    const double ratio =
        analysis.rest_stretch() / std::max(rms_stretch(sim.model(), sim.state()), 1e-300);
    verdict = format_text(tr("bounded; at rest acts as k_s x%.2g"), ratio);
    if (ratio < 0.5) color = Tone::Near;
  } else if (!resting && energy_account_closed(sim.model()) && back >= 2 && hist.net.size() == n &&
             hist.dissipated.size() == n) {
    const std::size_t a = n - back, b = n - 1;
    const double dt = hist.t[b] - hist.t[a];
    const double lost = -((hist.net[b] - hist.net[a]) + (hist.dissipated[b] - hist.dissipated[a]));
    // Negative: energy went into the springs' stretch, counted with k_s (XPBD at few passes).
    if (dt > 0.0 && lost >= 0.0)
      verdict = format_text(tr("bounded; damps %.2g W extra"), lost / dt);
    if (dt > 0.0 && lost < 0.0) {
      verdict = format_text(tr("bounded; +%.2g W into stretch"), -lost / dt);
      color = Tone::Near;
    }
  }
}

}  // namespace

GaugeVerdict gauge_verdict(const app::Lane& lane, const StabilityAnalysis* analysis, bool explain) {
  const Simulation& sim = lane.sim;
  const MethodInfo& m = method_info(sim.settings().method);
  const double h = sim.h();
  GaugeVerdict out;
  double& fraction = out.fraction;
  Tone& color = out.tone;
  std::string& verdict = out.text;
  verdict = tr("analysing...");
  const StabilityLimit* limit = analysis ? &analysis->limit(m.id) : nullptr;
  if (limit) {
    if (std::isnan(limit->h)) {
      fraction = 0.5;
      verdict = tr("adaptive");
    } else if (std::isinf(limit->h)) {
      fraction = std::min(1.0, h * analysis->w_max() / 10.0) * 0.6;
      color = Tone::Safe;
      verdict = tr("always stable");
      if (m.family == MethodFamily::Iterative) iterative_row_verdict(lane, *analysis, out);
    } else if (limit->h == 0.0) {
      fraction = 1.0;
      color = Tone::Beyond;
      verdict = tr("never stable");
    } else {
      const double ratio = h / limit->h;
      fraction = std::min(1.0, ratio / 1.5);
      color = ratio > 1.0   ? (limit->exact ? Tone::Beyond : Tone::Near)
              : ratio > 0.8 ? Tone::Near
                            : Tone::Safe;
      verdict =
          format_text(ratio > 1.0 ? (limit->exact ? tr("beyond: %.2fx") : tr("past proven: %.2fx"))
                      : ratio > 0.8 ? tr("near: %.2fx")
                                    : tr("safe: %.2fx"),
                      ratio);
    }
  }
  // A step of one's own that the homework checker found to be no row of the table: its row is a
  // stand-in, whose limit and claims are not its own.
  const bool unknown = !lane.own.empty() && !lane.own_known;
  if (unknown) {
    fraction = 0.5;
    color = Tone::Neutral;
    verdict = tr("not a textbook method: no stated limit");
  }
  // A free body: the momentum the method changes (momentum.hpp), said where it is more than a
  // rounding or a solver's tolerance would make it (the method table says what each keeps).
  std::string& momentum_line = out.momentum;
  const app::MassSpringLane* part = app::mass_spring_lane(lane);  // (its momentum, its cells)
  if (part && part->free_since && !sim.trouble() && !unknown) {
    const MomentumChange d = momentum_change(*part->free_since, momentum(sim.model(), sim.state()));
    momentum_line = format_text(
        tr("a free body: its momentum changed by %s of sum m|v|, its angular momentum by %s; "
           "%s: P %s, L %s"),
        format_text("%.2g", d.linear).c_str(), format_text("%.2g", d.angular).c_str(), tr(m.label),
        tr(kept_text(m.momentum)), tr(kept_text(m.angular_momentum)));
    if (d.linear > kMomentumVisible) {
      verdict += format_text(tr("; momentum off by %.2g%%"), 100.0 * d.linear);
      color = Tone::Near;
    }
  }
  if (part && part->inverted_cells > 0 && !sim.trouble()) {
    verdict += format_text(tr("; %d cells inverted"), part->inverted_cells);
    color = Tone::Near;
  }
  if (const Divergence* trouble = sim.trouble()) {
    color = Tone::Beyond;
    verdict = explain ? format_text(
                            trouble->unstable ? tr("unstable at %.3g s") : tr("diverged at %.3g s"),
                            trouble->t)
                      : std::string(trouble->unstable ? tr("unstable") : tr("diverged"));
  }
  return out;
}

}  // namespace springlab::ui
