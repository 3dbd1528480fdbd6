// Energy: on the undamped oscillator each linear method multiplies the energy by a known factor
// every step (its amplification squared), exactly, because its step is a scaled rotation in the
// coordinates (w x, v). Symplectic Euler and Verlet keep it bounded with no drift; dissipation
// (drag, friction) brings scenes to rest.
#include <gtest/gtest.h>

#include <cmath>

#include "springlab/colliders.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// On the linear oscillator (amplitude 0.5, E0 = 12.5 J).
double energy_after(Method method, double h, int steps) {
  SimulationSettings s;
  s.method = method;
  s.dt = h;
  s.audit_fraction = 0.0;  // the growth itself is what is measured
  const Scene scene = test::linear_oscillator();
  Simulation sim(scene.model, scene.state, s);
  EXPECT_EQ(sim.advance(steps), steps);
  return sim.energy().total();
}

TEST(Energy, ExplicitEulerGainsExactlyOnePlusHWSquaredEachStep) {
  const double h = 0.01, s = 0.01;  // (h w)^2 with w = 10
  const double expected = std::pow(1 + s, 500);
  EXPECT_NEAR(energy_after(Method::Euler, h, 500) / 12.5, expected, 1e-9 * expected);
}

TEST(Energy, ImplicitEulerLosesExactlyThatFactor) {
  const double h = 0.05, s = 0.25;
  const double expected = std::pow(1 + s, -200);
  EXPECT_NEAR(energy_after(Method::ImplicitEuler, h, 200) / 12.5, expected, 1e-9 * expected);
}

TEST(Energy, MidpointAndRK4FollowTheirAmplification) {
  const double h = 0.1, z = 1.0, s = z * z;
  const double midpoint = std::pow(1 + s * s / 4, 40);
  EXPECT_NEAR(energy_after(Method::Midpoint, h, 40) / 12.5, midpoint, 1e-9 * midpoint);
  const double r4 = 1 - std::pow(z, 6) / 72 + std::pow(z, 8) / 576;  // |R(i z)|^2
  const double rk4 = std::pow(r4, 1000);
  EXPECT_NEAR(energy_after(Method::RK4, h, 1000) / 12.5, rk4, 1e-9 * rk4);
  // Above RK4's limit (h w = 2.9) the same factor grows it: 1.424 a step.
  const double r4u = 1 - std::pow(2.9, 6) / 72 + std::pow(2.9, 8) / 576;
  EXPECT_NEAR(energy_after(Method::RK4, 0.29, 20) / 12.5, std::pow(r4u, 20),
              1e-9 * std::pow(r4u, 20));
}

TEST(Energy, SymplecticEulerAndVerletStayBoundedOverAHundredThousandSteps) {
  for (Method method : {Method::SymplecticEuler, Method::Verlet}) {
    const double hw = 1.0;  // the limit is 2
    Simulation sim = test::simulation(test::linear_oscillator(), method, hw / 10);
    const double E0 = sim.energy().total();
    double first_max = 0, last_max = 0, lowest = 1e300, highest = 0;
    for (int k = 0; k < 100000; ++k) {
      ASSERT_TRUE(sim.step());
      const double E = sim.energy().total();
      lowest = std::min(lowest, E);
      highest = std::max(highest, E);
      if (k < 1000) first_max = std::max(first_max, E);
      if (k >= 99000) last_max = std::max(last_max, E);
    }
    // Bounded: symplectic Euler exactly conserves H = E - h w^2 x v / 2, and |h w^2 x v / 2| <=
    // (h w / 2) E, so starting at rest E stays in [E0 / (1 + h w/2), E0 / (1 - h w/2)]; Verlet's
    // invariant is tighter. No drift: the peak is the same at the end as at the start.
    EXPECT_LE(highest, E0 / (1 - hw / 2) * (1 + 1e-9)) << method_info(method).name;
    EXPECT_GE(lowest, E0 / (1 + hw / 2) * (1 - 1e-9)) << method_info(method).name;
    EXPECT_NEAR(last_max, first_max, 1e-6 * E0) << method_info(method).name;
  }
}

TEST(Energy, ExplicitEulerGainsAndImplicitEulerLosesOnEveryScene) {
  // Every shipped scene with springs, made conservative (no spring damping, no drag, no
  // colliders; gravity kept: it conserves energy): explicit Euler only gains energy, implicit
  // Euler only loses it, at h w <= 0.1 over 200 steps (w Gershgorin's bound on the highest
  // frequency, from the quick bound on symplectic Euler's limit, about 2 / w: the fastest mode
  // grows at most 1.01^200 = 7.3 times under Euler, so nothing diverges). The change is past
  // rounding: at least 1e-12 of the energy scale.
  int scenes = 0;
  for (const char* name :
       {"spring", "damped-spring", "rope", "chain", "cloth", "cloth-sphere", "jelly", "stiff"}) {
    Scene scene = test::shipped(name);
    set_damping(scene.model, 0.0);
    scene.model.drag = 0.0;
    scene.model.planes.clear();
    scene.model.spheres.clear();
    const double h = 0.05 * quick_limit(Method::SymplecticEuler, scene.model, scene.state).h;
    for (auto [method, gains] : {std::pair{Method::Euler, true}, {Method::ImplicitEuler, false}}) {
      SimulationSettings s;
      s.method = method;
      s.dt = h;
      s.audit_fraction = 0.0;
      Simulation sim(scene.model, scene.state, s);
      const double E0 = sim.energy().total();
      ASSERT_EQ(sim.advance(200), 200) << name;
      const double change = sim.energy().total() - E0, rounding = 1e-12 * sim.energy_scale();
      if (gains)
        EXPECT_GT(change, rounding) << name << ", " << method_info(method).name;
      else
        EXPECT_LT(change, -rounding) << name << ", " << method_info(method).name;
    }
    ++scenes;
  }
  EXPECT_EQ(scenes, 8);
}

TEST(Dissipation, DragAndFrictionBringScenesToRest) {
  for (const char* name : {"jelly", "chain"}) {
    const Scene scene = test::shipped(name);
    Simulation sim = test::simulation(scene, scene.methods.front(), scene.dt, scene.substeps);
    const auto steps = static_cast<std::int64_t>(scene.duration / scene.dt);
    ASSERT_EQ(sim.advance(steps), steps) << name;
    EXPECT_LT(sim.energy().kinetic, 1e-3) << name;
  }
}

TEST(Dissipation, TrackedLossesAccountForTheEnergyThatGoes) {
  // Damped spring, fine steps of RK4 (its energy error (h w)^6 / 72 a step is 1e-14): energy +
  // dissipated stays the initial energy, to the quadrature's own error. The dissipated energy is
  // the power at each step's start times h, the left rectangle rule, whose error is
  // h (P(0) - P(T)) / 2 + O(h^2 P'): with P(0) = 0 (released at rest) the sum is the integral
  // plus -h P(T) / 2, and what is left is below 1e-7 J (a 0.1 % error in the dissipated 12.47 J
  // would be 1.2e-2 J).
  Scene scene = test::shipped("damped-spring");
  SimulationSettings s;
  s.method = Method::RK4;
  s.dt = 1e-3;
  s.track_dissipation = true;
  Simulation sim(scene.model, scene.state, s);
  sim.advance(3000);
  EXPECT_LT(sim.energy().total(), 0.5 * 12.5);
  const double end_power = dissipation_power(sim.model(), sim.state());
  EXPECT_NEAR(sim.energy().total() + sim.dissipated() + 0.5 * s.dt * end_power, 12.5, 1e-7);
}

// One free particle above a ground plane.
Simulation particle_on_ground(const Vec3& x0, const Vec3& v0, double friction, double restitution,
                              double dt) {
  Model m;
  add_particle(m, 1.0, false);
  m.gravity = Vec3(0, -9.81, 0);
  m.planes.push_back({Vec3::Zero(), Vec3::UnitY(), friction, restitution});
  finalize(m);
  State s;
  s.resize(1);
  s.x.row(0) = x0.transpose();
  s.v.row(0) = v0.transpose();
  SimulationSettings settings;
  settings.method = Method::SymplecticEuler;
  settings.dt = dt;
  return Simulation(m, s, settings);
}

TEST(Contact, CoulombFrictionStopsASlidingParticleAfterVSquaredOverTwoMuG) {
  const double v0 = 3.0, mu = 0.4, g = 9.81;
  Simulation sim = particle_on_ground(Vec3::Zero(), Vec3(v0, 0, 0), mu, 0.0, 1e-4);
  sim.advance(20000);  // 2 s; it stops after v0 / (mu g) = 0.76 s
  EXPECT_NEAR(sim.state().x(0, 0), v0 * v0 / (2 * mu * g), 0.01 * v0 * v0 / (2 * mu * g));
  EXPECT_NEAR(sim.state().v(0, 0), 0.0, 1e-12);
  EXPECT_GE(sim.state().x(0, 1), 0.0);
}

TEST(Contact, RestitutionReturnsEToTheSquareOfTheHeight) {
  const double e = 0.5, height = 1.0;
  Simulation sim = particle_on_ground(Vec3(0, height, 0), Vec3::Zero(), 0.0, e, 1e-5);
  double apex = 0.0;
  bool bounced = false;
  for (int k = 0; k < 100000; ++k) {  // 1 s: falls in 0.45 s, rises for 0.23 s
    sim.step();
    if (sim.state().v(0, 1) > 0) bounced = true;
    if (bounced) apex = std::max(apex, sim.state().x(0, 1));
  }
  EXPECT_NEAR(apex, e * e * height, 0.01 * e * e * height);
}

TEST(Contact, SphereHoldsAParticleOnTopAndLetsItSlideOffWithoutFriction) {
  Model m;
  add_particle(m, 1.0, false);
  m.gravity = Vec3(0, -9.81, 0);
  m.spheres.push_back({Vec3::Zero(), 1.0, 0.0, 0.0});
  finalize(m);
  State s;
  s.resize(1);
  s.x.row(0) << 0.0, 1.0, 0.0;
  s.v.setZero();
  State pushed = s;
  pushed.x(0, 0) = 0.05;
  State on_top = s;
  for (int k = 0; k < 1000; ++k) {
    on_top.x += 1e-3 * on_top.v;
    on_top.v.row(0) += 1e-3 * m.gravity.transpose();
    resolve_contacts(m, on_top);
  }
  EXPECT_NEAR(on_top.x(0, 1), 1.0, 1e-9);  // balanced exactly on top: stays
  SimulationSettings settings;
  settings.dt = 1e-4;
  Simulation sim(m, pushed, settings);
  sim.advance(30000);
  EXPECT_LT(sim.state().x(0, 1), 0.5);                 // slid off round the side
  EXPECT_GE(sim.state().x.row(0).norm(), 1.0 - 1e-9);  // never inside
}

}  // namespace
}  // namespace springlab
