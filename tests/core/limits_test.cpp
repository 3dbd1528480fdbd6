// The stated limits on every shipped scene with springs (and the 64- and 1000-node ropes and the
// 64 x 64 cloth), for every fixed-step method: a run at 0.95 times the stated limit holds, and at
// 1.25 times the limiting mode grows at the rate the analysis predicts, so that the run diverges
// wherever that growth is fast enough to show within the scene's duration.
//
// Runs are as the scene ships, for its duration, within a budget of work (a 1000-node rope under
// explicit Euler at 2e-6 s would take 5 million steps: the test runs as much of it as the budget
// allows, and says so, the energy audit's windows shortened to look six times within it;
// scripts/limits.sh runs them all to the end, in about an hour). The two single springs are run at
// a tenth of their shipped amplitude: the limit is that of small motions, and near the limits of
// symplectic Euler and RK4 the numerical orbit of the shipped one (half the rest length) passes
// through the anchor into the spring's other well, where RK4 even keeps up a limit cycle against
// the damping, which the audit rightly reports (Stability.TheAuditCatches... tests).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>

#include "springlab/energy_audit.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

struct LimitCase {
  std::string scene;
  std::vector<std::string> overrides;
  std::string name() const {
    std::string n = scene;
    for (const auto& o : overrides) n += " " + o;
    return n;
  }
};

std::vector<LimitCase> cases() {
  return {{"spring", {"particles.1.position=[1.05,0,0]"}},
          {"damped-spring", {"particles.1.position=[1.05,0,0]"}},
          {"rope", {}},
          {"chain", {}},
          {"cloth", {}},
          {"cloth-sphere", {}},
          {"jelly", {}},
          {"stiff", {}},
          {"rope", {"rope.nodes=64"}},
          {"rope", {"rope.nodes=1000"}},
          {"cloth", {"cloth.width=64", "cloth.height=64"}}};
}

const std::vector<Method> kMethods = test::explicit_fixed_step();

// Particle- and spring-steps a run may take (about a second here); SPRINGLAB_LIMITS_BUDGET sets
// another (scripts/limits.sh: enough for every run's whole duration).
double budget() {
  const char* set = std::getenv("SPRINGLAB_LIMITS_BUDGET");
  return set ? std::atof(set) : 2e8;
}

struct Outcome {
  bool held = true;           // no divergence, no instability from the audit
  double t = 0.0;             // simulated
  bool whole = true;          // ran the scene's whole duration
  std::int64_t windows = 0;   // the audit's windows in the run
  std::int64_t possible = 0;  // as many as the run had room for (8 checks each at least)
  std::string said;
};

// A run as long as the scene's duration, or as the budget allows; the audit's windows as short as
// needed for at least six of them in it (a run the budget cuts to 0.07 s of simulated time, shorter
// than the audit's own 0.25 s windows, would otherwise hold without the audit ever looking).
Outcome run(const Scene& scene, Method method, double h,
            const std::shared_ptr<const StabilityAnalysis>& analysis) {
  const double evals = method == Method::Midpoint ? 2 : method == Method::RK4 ? 4 : 1;
  const double size = scene.model.particle_count() + scene.model.spring_count();
  const auto wanted = static_cast<std::int64_t>(std::ceil(scene.duration / h));
  const auto allowed = static_cast<std::int64_t>(std::min(9e18, budget() / (evals * size)));
  const std::int64_t steps = std::min(wanted, allowed);
  SimulationSettings s;
  s.method = method;
  s.dt = h;
  s.audit_window = std::min(EnergyAudit::kWindow, steps * h / 6.0);
  Simulation sim(scene.model, scene.state, s);
  sim.set_stability(
      analysis);  // the scene's, made once (the audit asks for it when a window rises)
  Outcome o;
  o.whole = wanted <= allowed;
  sim.advance(steps);
  o.t = sim.state().t;
  o.windows = sim.audit_windows();
  const std::int64_t checks = size <= kSmallScene ? steps : steps / 16;
  o.possible = std::min<std::int64_t>(6, checks / EnergyAudit::kChecks);
  o.held = !sim.diverged();
  if (!o.held) o.said = sim.divergence()->message();
  return o;
}

// The growth of the limiting mode at h in the linear regime: the scene at its equilibrium pushed
// a little along the mode, stepped n times; the mode's amplitude (the displacement projected on
// the mode's shape, mass-weighted: the other modes hardly show in it) against rho^n.
double measured_growth_rate(const Scene& scene, Method method, const LimitingMode& mode, double h,
                            int n) {
  SimulationSettings s;
  s.method = method;
  s.dt = h;
  s.audit_fraction = 0.0;
  Model model = scene.model;
  model.planes.clear();
  model.spheres.clear();
  const State rest = equilibrium(model, scene.state);
  State pushed = rest;
  double size = 0.0;
  for (int c = 0; c < 3; ++c)
    size = std::max(size, rest.x.col(c).maxCoeff() - rest.x.col(c).minCoeff());
  pushed.x += (1e-6 * std::max(size, 1e-3)) * mode.shape;
  Simulation sim(model, pushed, s);
  double norm = 0.0;
  for (int i = 0; i < model.particle_count(); ++i)
    norm += model.mass[i] * mode.shape.row(i).squaredNorm();
  const auto amplitude = [&] {
    double p = 0.0;
    for (int i = 0; i < model.particle_count(); ++i)
      p += model.mass[i] * (sim.state().x.row(i) - rest.x.row(i)).dot(mode.shape.row(i));
    return std::abs(p) / norm;
  };
  // The largest amplitude over a period's steps (the mode oscillates within it), at the start and
  // n steps on.
  const int stretch = std::max(4, static_cast<int>(std::ceil(2.0 * M_PI / (mode.w * h))) + 1);
  const auto peak = [&] {
    double best = 0.0;
    for (int k = 0; k < stretch; ++k) {
      sim.step();
      best = std::max(best, amplitude());
    }
    return best;
  };
  const double early = peak();
  sim.advance(n);
  const double late = peak();
  return std::log(late / early) / (n + stretch);
}

class Limits : public ::testing::TestWithParam<LimitCase> {};

TEST_P(Limits, HoldJustInsideAndGrowAsPredictedJustOutside) {
  const LimitCase& c = GetParam();
  const Scene scene = test::shipped(c.scene, c.overrides);
  const auto shared = std::make_shared<const StabilityAnalysis>(scene.model, scene.state);
  const StabilityAnalysis& analysis = *shared;
  ASSERT_TRUE(analysis.oscillates()) << c.name();
  for (Method m : kMethods) {
    const StabilityLimit& limit = analysis.limit(m);
    SCOPED_TRACE(c.name() + ", " + method_info(m).name + ": " + describe(limit));
    if (!(limit.h > 0.0 && std::isfinite(limit.h))) {
      // Unstable at any step (an undamped spring under explicit Euler): it fails at a small one.
      if (limit.h == 0.0) {
        EXPECT_FALSE(run(scene, m, 0.5 / analysis.w_max(), shared).held);
      }
      continue;
    }
    const Outcome inside = run(scene, m, 0.95 * limit.h, shared);
    EXPECT_TRUE(inside.held) << inside.said;
    // The audit looked, window after window, and stayed silent (symplectic Euler and Verlet are
    // not audited: the divergence test watches them).
    if (method_info(m).audited) {
      EXPECT_GE(inside.windows, inside.possible - 1);
    }
    std::printf("  %-28s %-17s %-34s 0.95: held %.3g s%s", c.name().c_str(), method_info(m).name,
                describe(limit).c_str(), inside.t, inside.whole ? "" : " (budget)");

    const Outcome outside = run(scene, m, 1.25 * limit.h, shared);
    if (!outside.held) {
      std::printf(", 1.25: diverged at %.3g s\n", outside.t);
      continue;
    }
    // It held: then the growth must be too slow to show in the time it ran. The analysis says
    // how fast (a mode multiplied by rho a step), and, for an exact limit, a run in the linear
    // regime says the same.
    ASSERT_TRUE(limit.mode);
    const double h = 1.25 * limit.h;
    const double rho =
        amplification(m, limit.mode->w, limit.mode->c, h, method_parameters(scene.model));
    const double grown = 2.0 * std::log(rho) * outside.t / h;  // ln of the energy's growth
    std::printf(", 1.25: held %.3g s%s, the mode's energy growing e^%.3g there\n", outside.t,
                outside.whole ? "" : " (budget)", grown);
    if (limit.exact) {
      EXPECT_GT(rho, 1.0);
      EXPECT_LT(grown, std::log(1e8)) << "grows fast enough to diverge within the run, yet held";
      // For the Runge-Kutta methods the mode is an eigenvector of the system at any step (A's
      // eigenvectors do not depend on h): pushed along it, the scene grows at its rate, over the
      // steps that multiply it by about e. (Modified Euler's eigenvectors move with h: its damping
      // is C^ + h K^ / 2.)
      if (m == Method::Euler || m == Method::Midpoint || m == Method::RK4) {
        const int n = std::max(200, static_cast<int>(std::min(2e5, 1.0 / std::log(rho))));
        const double rate = measured_growth_rate(scene, m, *limit.mode, h, n);
        EXPECT_NEAR(rate, std::log(rho), 0.2 * std::log(rho)) << "n = " << n;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Limits, ::testing::ValuesIn(cases()), [](const auto& info) {
  std::string n = info.param.name();
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

}  // namespace
}  // namespace springlab
