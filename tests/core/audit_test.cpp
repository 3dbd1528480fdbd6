// The energy audit told both ways (energy_audit.hpp): silent on every stable run, firing on the
// runs that grow or saturate. Its pieces first (the transient growth it allows, the energy's
// lower bound, the windows' rule on made-up sequences), then runs: a sweep of stable single
// springs, the hanging rope and cloth just inside their limits, and the instabilities it must
// still catch.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "springlab/energy_audit.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- The transient growth
// ------------------------------------------------------------------------

// sup_n |S^n|^2 is a property of the method's real step: the linear spring started from every
// phase of its energy ellipse and run with Simulation (the method as it runs) never gains more
// than that factor, and some start gains nearly all of it.
double largest_gain_by_runs(Method method, double w, double c, double h, int steps) {
  const Scene spring = test::linear_oscillator(w * w, c);
  double largest = 0.0;
  for (int k = 0; k < 64; ++k) {
    // (Not the phase that starts on the anchor: there a zero-length spring has no direction.)
    const double phase = 2.0 * M_PI * (k + 0.5) / 64.0;
    State start = spring.state;
    start.x(1, 0) = 0.1 * std::cos(phase) / w;  // energy (w^2 x^2 + v^2) / 2 = 0.005 J
    start.v(1, 0) = 0.1 * std::sin(phase);
    SimulationSettings s;
    s.method = method;
    s.dt = h;
    s.audit_fraction = 0.0;
    Simulation sim(spring.model, start, s);
    const double e0 = sim.energy().total();
    for (int n = 0; n < steps && sim.step(); ++n)
      largest = std::max(largest, sim.energy().total() / e0);
  }
  return largest;
}

TEST(TransientGrowth, BoundsWhatTheMethodsOwnStepsGain) {
  struct Case {
    Method method;
    double c, fraction;
  };
  // w = 10; damping ratios 0.1 and 1, near the limits where the step is least normal.
  const Case cases[] = {{Method::Euler, 2.0, 0.98},         {Method::Euler, 20.0, 0.9},
                        {Method::Midpoint, 2.0, 0.95},      {Method::Midpoint, 20.0, 0.98},
                        {Method::ModifiedEuler, 2.0, 0.95}, {Method::ModifiedEuler, 8.0, 0.9},
                        {Method::RK4, 2.0, 0.98},           {Method::RK4, 20.0, 0.98},
                        {Method::ImplicitEuler, 2.0, 0.0}};
  for (const Case& c : cases) {
    const double limit = stable_step(c.method, 10.0, c.c);
    const double h = std::isinf(limit) ? 0.5 : c.fraction * limit;
    const double g = transient_growth(c.method, c.c, 100.0, h);
    const double by_runs = largest_gain_by_runs(c.method, 10.0, c.c, h, 400);
    SCOPED_TRACE(std::string(method_info(c.method).name) + " c = " + std::to_string(c.c) +
                 " h = " + std::to_string(h));
    ASSERT_TRUE(std::isfinite(g));
    EXPECT_LE(by_runs, g * (1.0 + 1e-9));  // never more than the bound
    if (g > 1.01) {
      EXPECT_GE(by_runs, 1.0 + 0.9 * (g - 1.0));  // and the bound is (almost) reached
    }
  }
  // A normal contraction cannot raise a mode's energy at all: implicit Euler's step on a
  // damped mode (its linearised solve is exact on a linear spring).
  EXPECT_NEAR(transient_growth(Method::ImplicitEuler, 2.0, 100.0, 0.05), 1.0, 1e-4);
  // Critical damping near midpoint's limit: a thousandfold (a Jordan block's n rho^n).
  EXPECT_GT(transient_growth(Method::Midpoint, 20.0, 100.0,
                             0.98 * stable_step(Method::Midpoint, 10.0, 20.0)),
            500.0);
  // Past a limit the mode grows: no bound.
  EXPECT_TRUE(std::isinf(transient_growth(Method::Euler, 2.0, 100.0, 1.01 * 0.02)));
  EXPECT_TRUE(
      std::isinf(transient_growth(Method::Euler, 0.0, 100.0, 1e-4)));  // undamped: never stable
  EXPECT_EQ(transient_growth(Method::RK4, 3.0, 0.0, 0.1), 1.0);        // a drag-only decay
}

// ---- The energy's lower bound
// --------------------------------------------------------------------

TEST(LowestEnergy, IsTheBalanceForHeldPartsAndTheFloorForFreeOnes) {
  // A hanging rope: its equilibrium's energy, below every state it passes through.
  const Scene rope = test::shipped("rope");
  const StabilityAnalysis hanging(rope.model, rope.state);
  EXPECT_NEAR(hanging.lowest_energy(),
              energy(rope.model, equilibrium(rope.model, rope.state)).total(), 1e-9);
  Simulation sim = test::simulation(rope, Method::RK4, 1e-3);
  for (int k = 0; k < 3000; ++k) {
    sim.step();
    ASSERT_GE(sim.energy().total(), hanging.lowest_energy() - 1e-9) << "t = " << sim.state().t;
  }
  // A free box above the ground: every particle on the floor (its plane plus a radius), springs
  // at rest.
  const Scene jelly = test::shipped("jelly");
  const StabilityAnalysis box(jelly.model, jelly.state);
  double floor = 0.0;
  for (int i = 0; i < jelly.model.particle_count(); ++i)
    floor += jelly.model.mass[i] * 9.81 *
             (jelly.model.planes.front().point.y() + jelly.model.particle_radius);
  EXPECT_NEAR(box.lowest_energy(), floor, 1e-9 * std::abs(floor) + 1e-12);
  // The same box with no floor can fall forever: no bound.
  Scene falling = jelly;
  falling.model.planes.clear();
  EXPECT_EQ(StabilityAnalysis(falling.model, falling.state).lowest_energy(), -kInf);
}

// ---- The rule, on made-up sequences
// ---------------------------------------------------------------

// Feeds N(t) (and E = N + 10) at 100 checks a second for `seconds`; returns the finding.
template <typename Net>
std::optional<EnergyAudit::Finding> feed(EnergyAudit& audit,
                                         const EnergyAudit::Allowance& allowance, double seconds,
                                         const Net& net, double floor = 1e-3,
                                         double* found_at = nullptr) {
  for (int k = 1; k <= static_cast<int>(seconds * 100); ++k) {
    const double t = k / 100.0, n = net(t);
    audit.record(t, k, n, n + 10.0, floor);
    if (!audit.pending()) continue;
    if (auto f = audit.decide(allowance, floor)) {
      if (found_at) *found_at = t;
      return f;
    }
  }
  return std::nullopt;
}

TEST(EnergyAuditRule, FallingOrLevelEnergyIsNeverAsked) {
  EnergyAudit audit;
  for (int k = 1; k <= 1000; ++k) {
    audit.record(k / 100.0, k, -0.01 * k + 0.5 * std::sin(k) * 1e-4, 10.0,
                 1e-3);  // falls, wobbling below the floor
    EXPECT_FALSE(audit.pending()) << k;
  }
}

TEST(EnergyAuditRule, ARiseWithinTheAllowanceIsSilent) {
  // U at the low is E - E_low = 10 - 0 J; G = 1.1 allows 2 (G - 1) U = 2 J. Bumps of 1.9 J
  // above the low recurring every half second, the low never falling: silent.
  EnergyAudit audit;
  const auto bumps = [](double t) { return 1.9 * std::pow(std::sin(2.0 * M_PI * t), 2.0); };
  EXPECT_FALSE(feed(audit, {1.1, 0.0}, 20.0, bumps));
  // The same bumps with G = 1.05 (1 J allowed): found, the rise and what was allowed said.
  EnergyAudit strict;
  const auto f = feed(strict, {1.05, 0.0}, 20.0, bumps);
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->rise, 1.9, 0.01);
  EXPECT_NEAR(f->allowed, 1.0 + 1e-3, 1e-9);
  EXPECT_NEAR(f->motion, 10.0, 1e-9);
}

TEST(EnergyAuditRule, OneWindowOverIsNotEnoughTwoInARowAre) {
  // A single spike (a contact's push, say) in one window: silent. A rise that stays: found in
  // its second window, not its first.
  EnergyAudit once;
  EXPECT_FALSE(
      feed(once, {1.0, 0.0}, 5.0, [](double t) { return t > 2.0 && t < 2.05 ? 1.0 : -t * 1e-3; }));
  EnergyAudit stays;
  double at = 0.0;
  ASSERT_TRUE(feed(
      stays, {1.0, 0.0}, 5.0, [](double t) { return t > 2.0 ? 1.0 : 0.0; }, 1e-3, &at));
  EXPECT_GT(at, 2.0 + EnergyAudit::kWindow);
  EXPECT_LE(at, 2.0 + 3.0 * EnergyAudit::kWindow + 0.011);
}

TEST(EnergyAuditRule, GrowthPastTheFloorIsFoundWhereNothingElseIsAllowed) {
  // G = 1 (no stable mode can raise its energy) and no lower bound on E: any rise past the floor
  // counts; a compounding one (x1.01 a check from 1e-6) is found once past it, not before.
  EnergyAudit audit;
  double at = 0.0;
  const auto f = feed(
      audit, {1.0, -kInf}, 10.0, [](double t) { return 1e-6 * std::pow(1.01, 100.0 * t); }, 1e-3,
      &at);
  ASSERT_TRUE(f);
  EXPECT_GT(f->rise, 1e-3);
  EXPECT_GT(at, std::log(1e3) / (100.0 * std::log(1.01)));  // when the rise passed the floor
  // With G > 1 and no lower bound the allowance is unbounded: never.
  EnergyAudit blind;
  EXPECT_FALSE(
      feed(blind, {1.5, -kInf}, 10.0, [](double t) { return 1e-6 * std::pow(1.01, 100.0 * t); }));
}

TEST(EnergyAuditRule, ResetForgetsTheLows) {
  // A low before reset() is not a low after it (a new step, a new method, a drag released).
  EnergyAudit audit;
  EXPECT_FALSE(feed(audit, {1.0, 0.0}, 2.0, [](double t) { return -t; }));
  EnergyAudit kept = audit;
  audit.reset();
  for (int k = 1; k <= 300; ++k) {
    audit.record(2.0 + k / 100.0, k, 0.0, 10.0, 1e-3);  // level at 0, above the -2 before
    kept.record(2.0 + k / 100.0, k, 0.0, 10.0, 1e-3);
  }
  EXPECT_FALSE(audit.pending());
  EXPECT_TRUE(kept.pending());  // without the reset, the old low makes it a rise
}

// ---- Runs that must stay silent
// --------------------------------------------------------------------

struct Silence {
  bool held = true;
  std::string said;
};

Silence run_for(const Scene& scene, Method method, double h, double duration) {
  SimulationSettings s;
  s.method = method;
  s.dt = h;
  Simulation sim(scene.model, scene.state, s);
  sim.advance(static_cast<std::int64_t>(std::ceil(duration / h)));
  Silence out;
  out.held = !sim.diverged();
  if (!out.held) out.said = sim.divergence()->message();
  return out;
}

// Every fixed-step method on a single spring (k_s = 100, m = 1: w = 10), damping ratios from
// 0.02 to 4 (critical at 1, overdamped past it), steps from 0.2 to 0.98 of the stated limit (those
// stable at any step: h w from 0.2 to 20), 20 periods: none stops. The linear spring (rest length
// 0) and the shipped one (rest length 1, 1 mm from rest: near critical damping RK4 and midpoint
// raise a mode's energy up to a thousandfold before it decays, which from the shipped 5 cm would
// carry it through the anchor).
TEST(AuditSilence, EveryStableSingleSpring) {
  const double ratios[] = {0.02, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 4.0};  // to overdamped
  const double fractions[] = {0.2, 0.5, 0.8, 0.9, 0.95, 0.98};
  const std::vector<Method> fixed = test::fixed_step();
  int runs = 0;
  for (bool linear : {true, false}) {
    for (double zeta : ratios) {
      const double kd = 2.0 * zeta * 10.0;
      Scene spring = linear ? test::linear_oscillator(100.0, kd) : test::oscillator(100.0, kd);
      if (!linear) spring.state.x(1, 0) = 1.001;
      const StabilityAnalysis analysis(spring.model, spring.state);
      for (Method m : fixed) {
        const double limit = analysis.limit(m).h;
        for (double f : fractions) {
          // Stable at any step (implicit Euler, the iterative rows): h w = 0.2, 2 and 20.
          const double h = !std::isinf(limit) ? f * limit
                           : f == 0.2         ? 0.02
                           : f == 0.5         ? 0.2
                           : f == 0.8         ? 2.0
                                              : 0.0;
          if (!(h > 0.0)) continue;
          const Silence s = run_for(spring, m, h, 20 * 2.0 * M_PI / 10.0);
          EXPECT_TRUE(s.held) << (linear ? "linear" : "rest length 1") << " spring, damping ratio "
                              << zeta << ", " << method_info(m).name << " at " << f << " of "
                              << limit << " s: " << s.said;
          ++runs;
        }
      }
    }
  }
  const int explicit_methods = static_cast<int>(test::explicit_fixed_step().size());
  const int any_step = static_cast<int>(
      test::methods_where([](const MethodInfo& m) { return m.any_step(); }).size());
  EXPECT_EQ(runs, 2 * static_cast<int>(std::size(ratios)) * (explicit_methods * 6 + any_step * 3));
}

// The hanging rope and cloth at 0.9 of each audited method's stated limit, for 20 periods of the
// slowest mode (the rope's swing: w = 1.85 rad/s, 68 s) and the cloth's shipped 10 s.
TEST(AuditSilence, TheRopeAndTheClothJustInsideTheirLimits) {
  for (const char* name : {"rope", "cloth"}) {
    const Scene scene = test::shipped(name);
    const StabilityAnalysis analysis(scene.model, scene.state);
    double slowest = kInf;
    for (const auto& m : analysis.modes())
      if (m.kappa > 0.0) slowest = std::min(slowest, std::sqrt(m.kappa));
    const double duration = analysis.dense() ? 20.0 * 2.0 * M_PI / slowest : scene.duration;
    // The audited methods with a limit (the others are the divergence test's, or have none).
    for (Method m :
         test::methods_where([](const MethodInfo& i) { return i.audited && !i.implicit(); })) {
      const double h = 0.9 * analysis.limit(m).h;
      const Silence s = run_for(scene, m, h, duration);
      EXPECT_TRUE(s.held) << name << ", " << method_info(m).name << " at h = " << h << " for "
                          << duration << " s: " << s.said;
    }
  }
}

// ---- Runs that must be caught
// ------------------------------------------------------------------------

// Past their limits by a quarter (the limits test's runs), runs whose growth nothing else catches
// within the scene's time (the divergence test needs a millionfold): the audit does, and says it
// was the audit.
TEST(AuditCatches, GrowthTheDivergenceTestWouldMiss) {
  struct Case {
    const char* scene;
    std::vector<std::string> overrides;
    Method method;
  };
  const Case cases[] = {
      {"spring", {"particles.1.position=[1.05,0,0]"}, Method::Midpoint},
      {"damped-spring", {"particles.1.position=[1.05,0,0]"}, Method::Euler},
      {"damped-spring", {"particles.1.position=[1.05,0,0]"}, Method::Midpoint},
      {"damped-spring", {"particles.1.position=[1.05,0,0]"}, Method::ModifiedEuler},
      {"cloth", {}, Method::Midpoint},
      {"cloth-sphere", {}, Method::Midpoint},
      {"cloth-sphere", {}, Method::ModifiedEuler}};
  for (const Case& c : cases) {
    const auto t0 = std::chrono::steady_clock::now();
    const Scene scene = test::shipped(c.scene, c.overrides);
    const StabilityAnalysis analysis(scene.model, scene.state);
    // (Unstable at any step, as undamped midpoint is: at h w_max = 0.5, as the limits test runs
    // it.)
    const double limit = analysis.limit(c.method).h;
    const double h = limit > 0.0 ? 1.25 * limit : 0.5 / analysis.w_max();
    SimulationSettings s;
    s.method = c.method;
    s.dt = h;
    const auto steps = static_cast<std::int64_t>(std::ceil(scene.duration / h));
    s.audit_fraction = 0.0;
    Simulation unaudited(scene.model, scene.state, s);
    unaudited.advance(steps);
    std::printf("  unaudited %.3g s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    EXPECT_FALSE(unaudited.diverged())
        << c.scene << ", " << method_info(c.method).name << ": the divergence test "
        << "alone catches it; the case proves nothing of the audit";
    s.audit_fraction = kAuditFraction;
    Simulation audited(scene.model, scene.state, s);
    audited.advance(steps);
    std::printf("%s %s %.3g s\n", c.scene, method_info(c.method).name,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ASSERT_TRUE(audited.diverged()) << c.scene << ", " << method_info(c.method).name;
    EXPECT_TRUE(audited.divergence()->unstable) << audited.divergence()->message();
  }
}

// Explicit Euler on an undamped spring is unstable at any step (lesson 3): its energy grows by
// (1 + (h w)^2) a step. Caught at every h w from 0.003 to 0.3, soon after the growth passes the
// floor (a thousandth of the 100 J scale: 0.8 % of its 12.5 J), and the rise it reports is the
// predicted one.
TEST(AuditCatches, ExplicitEulerOnAnUndampedSpringAtAnyStep) {
  const Scene spring = test::linear_oscillator();
  for (double hw : {0.003, 0.03, 0.3}) {
    const double h = hw / 10.0;
    SimulationSettings s;
    s.method = Method::Euler;
    s.dt = h;
    Simulation sim(spring.model, spring.state, s);
    const double floor_steps = std::log(1.0 + 0.1 / 12.5) / std::log(1.0 + hw * hw);
    sim.advance(static_cast<std::int64_t>(floor_steps + 4.0 * EnergyAudit::kWindow / h + 100));
    ASSERT_TRUE(sim.diverged()) << "h w = " << hw;
    const Divergence& d = *sim.divergence();
    EXPECT_TRUE(d.unstable) << d.message();
    // The energy is exactly 12.5 (1 + (h w)^2)^n J after n steps: the rise from the low (the
    // first check) to where it stopped.
    const double q = 1.0 + hw * hw;
    const double predicted =
        12.5 * std::pow(q, d.audit.low_step) * (std::pow(q, d.step - d.audit.low_step) - 1.0);
    EXPECT_NEAR(d.audit.rise, predicted, 1e-9 * predicted) << d.message();
    EXPECT_EQ(d.audit.low_step, 1);
  }
}

}  // namespace
}  // namespace springlab
