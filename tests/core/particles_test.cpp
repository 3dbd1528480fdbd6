// Particle systems against exact results: births at rate j / rate, deaths at their lifetime, a
// pool that is never exceeded, free flight on the exact parabola (even for a particle born between
// steps), a firework's sparks on a sphere about the shell's path, the attractor's derivative
// against finite differences, an orbit's energy, a wind's terminal velocity; and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "springlab/error.hpp"
#include "springlab/forces.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// A scene of one emitter (its fields as JSON text) and the rest of the top level.
Scene emitter_scene(const std::string& emitter,
                    const std::string& rest = R"("gravity": [0, -9.81, 0])") {
  return parse_scene(
      R"({"emitters": [{"name": "e", "position": [0, 1, 0], )" + emitter + "}], " + rest + "}",
      "test.json");
}

Simulation run(const Scene& scene, Method method, double dt, std::int64_t steps) {
  Simulation sim = test::simulation(scene, method, dt);
  EXPECT_EQ(sim.advance(steps), steps);
  return sim;
}

TEST(Emission, BirthsComeAtTheRateFromTheStart) {
  // Births at j / 64 s for j = 0, 1, ...: after 2 s (128 steps of 1/64), 129 of them.
  const Scene s = emitter_scene(R"("rate": 64, "lifetime": 100, "max": 1000)");
  const Simulation sim = run(s, Method::SymplecticEuler, 1.0 / 64, 128);
  EXPECT_EQ(sim.emission().born(), 129);
  EXPECT_EQ(sim.emission().alive_count(), 129);
  EXPECT_EQ(sim.emission().dropped(), 0);
}

TEST(Emission, ParticlesDieAtTheEndOfTheirLifetime) {
  // Lifetime 0.5 s: at t = 2 s the alive ones were born in (1.5, 2]: j = 97 ... 128.
  const Scene s = emitter_scene(R"("rate": 64, "lifetime": 0.5, "max": 1000)");
  const Simulation sim = run(s, Method::SymplecticEuler, 1.0 / 64, 128);
  EXPECT_EQ(sim.emission().alive_count(), 32);
  int alive = 0, free_particles = 0;
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    alive += sim.emission().alive(i);
    free_particles += !sim.model().pinned(i);
  }
  EXPECT_EQ(alive, 32);
  EXPECT_EQ(free_particles, 32);  // the dead are pinned: the integrators leave them be
}

TEST(Emission, ThePoolIsNeverExceededAndDropsAreCounted) {
  const Scene s = emitter_scene(R"("rate": 100, "lifetime": 1, "max": 10)");
  Simulation sim = test::simulation(s, Method::SymplecticEuler, 0.01);
  for (int k = 0; k < 300; ++k) {
    ASSERT_TRUE(sim.step());
    ASSERT_LE(sim.emission().alive_count(), 10);
  }
  // 301 births due by t = 3 s; each slot frees 1 s after its birth, so at most 10 + 10 + 10 + 10
  // happen (at 0, ~1, ~2 and ~3 s) and the rest are dropped.
  EXPECT_EQ(sim.emission().born() + sim.emission().dropped(), 301);
  EXPECT_LE(sim.emission().born(), 40);
  EXPECT_GE(sim.emission().born(), 30);
}

TEST(Emission, FreeFlightFollowsTheParabolaEvenWhenBornBetweenSteps) {
  // One particle, due at t_b = 0.013 s (between steps of 0.01 s), thrown at 5 m/s along
  // (1, 2, 0) / sqrt(5). Midpoint and RK4 are exact for a constant acceleration, and its birth
  // places it on the parabola at the next step, so it stays on it.
  const Scene s = emitter_scene(
      R"("rate": 1e-3, "start": 0.013, "speed": 5, "direction": [1, 2, 0], "lifetime": 100, "max": 1)");
  for (Method m : {Method::Midpoint, Method::RK4}) {
    const Simulation sim = run(s, m, 0.01, 100);
    ASSERT_EQ(sim.emission().alive_count(), 1);
    const int i = s.model.emitters[0].pool.first;
    const double tau = sim.state().t - 0.013;
    const Vec3 v0 = 5.0 * Vec3(1, 2, 0).normalized();
    const Vec3 expected = Vec3(0, 1, 0) + v0 * tau + 0.5 * tau * tau * Vec3(0, -9.81, 0);
    EXPECT_LT((sim.state().x.row(i).transpose() - expected).norm(), 1e-12) << method_info(m).name;
    EXPECT_LT((sim.state().v.row(i).transpose() - (v0 + tau * Vec3(0, -9.81, 0))).norm(), 1e-12);
  }
}

TEST(Emission, DirectionsFillTheirConeAndSpeedsTheirRange) {
  const Scene s = emitter_scene(
      R"("rate": 1000, "speed": 4, "speed_spread": 1, "direction": [0, 0, 1], "spread": 30, "lifetime": 10, "max": 1000)",
      R"("gravity": [0, 0, 0])");
  const Simulation sim = run(s, Method::SymplecticEuler, 0.001, 999);
  ASSERT_EQ(sim.emission().alive_count(), 1000);
  double widest = 0.0, mean_cos = 0.0;
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    const Vec3 v = sim.state().v.row(i).transpose();
    ASSERT_GE(v.norm(), 3.0);
    ASSERT_LE(v.norm(), 5.0);
    const double angle = std::acos(std::clamp(v.normalized().z(), -1.0, 1.0));
    widest = std::max(widest, angle);
    mean_cos += v.normalized().z() / 1000.0;
  }
  EXPECT_LE(widest, 30.0 * std::numbers::pi / 180.0 + 1e-12);
  EXPECT_GT(widest, 29.0 * std::numbers::pi / 180.0);  // and fill it
  // Uniform over the cap: the mean of cos(theta) is (1 + cos 30 deg) / 2, within a few
  // standard errors (the variance of cos over the cap is (1 - cos 30)^2 / 12).
  const double c = std::cos(std::numbers::pi / 6);
  EXPECT_NEAR(mean_cos, (1 + c) / 2, 4 * (1 - c) / std::sqrt(12.0 * 1000));
}

TEST(Emission, AShellBurstsIntoSparksOnASphereAboutItsPath) {
  // A shell thrown up at 10 m/s dies at t = 0.6 s; its 200 sparks leave at 3 m/s in every
  // direction. Without drag each spark's motion relative to where the shell would have gone is
  // uniform: they lie on a sphere of radius 3 (t - 0.6) about that point.
  const Scene s = emitter_scene(
      R"("rate": 1e-3, "speed": 10, "lifetime": 0.6, "max": 1, "burst": {"count": 200, "speed": 3, "lifetime": 5})");
  const Simulation sim = run(s, Method::RK4, 0.01, 100);
  const double t = sim.state().t;
  EXPECT_EQ(sim.emission().alive_count(), 200);
  const Vec3 shell = Vec3(0, 1, 0) + t * Vec3(0, 10, 0) + 0.5 * t * t * Vec3(0, -9.81, 0);
  const Pool& sparks = s.model.emitters[0].burst->pool;
  for (int i = sparks.first; i < sparks.first + 200; ++i)
    EXPECT_NEAR((sim.state().x.row(i).transpose() - shell).norm(), 3.0 * (t - 0.6), 1e-9);
}

TEST(Emission, TheSameSceneGivesTheSameBitsWhateverTheThreadCount) {
  const Scene s = test::shipped("fireworks");
  std::uint64_t hashes[2];
  for (int threads : {1, 2}) {
    set_thread_count(threads);
    hashes[threads - 1] = state_hash(run(s, Method::SymplecticEuler, s.dt, 600).state());
  }
  set_thread_count(0);
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(hashes[0], state_hash(run(s, Method::SymplecticEuler, s.dt, 600).state()));
}

TEST(Emission, ResetStartsTheEmissionAfresh) {
  const Scene s = test::shipped("fountain");
  Simulation sim = run(s, Method::SymplecticEuler, s.dt, 200);
  const std::uint64_t first = state_hash(sim.state());
  sim.reset();
  EXPECT_EQ(sim.emission().born(), 1);  // the birth due at t = 0
  sim.advance(200);
  EXPECT_EQ(state_hash(sim.state()), first);
}

TEST(Fields, TheAttractorsDerivativeMatchesFiniteDifferences) {
  Attractor f;
  f.center = Vec3(0.2, -0.1, 0.3);
  f.strength = 3.0;
  f.softening = 0.2;
  f.swirl = 1.5;
  f.axis = Vec3(1, 2, 2).normalized();
  for (const Vec3& x : {Vec3(1, 0.5, -0.4), Vec3(0.25, -0.05, 0.35), Vec3(-2, 3, 1)}) {
    const Eigen::Matrix3d J = field_jacobian(f, x);
    const double e = 1e-6;
    for (int c = 0; c < 3; ++c) {
      const Vec3 dx = e * Vec3::Unit(c);
      const Vec3 column = (field_acceleration(f, x + dx) - field_acceleration(f, x - dx)) / (2 * e);
      EXPECT_LT((J.col(c) - column).norm(), 1e-6 * (1 + column.norm())) << "column " << c;
    }
  }
}

TEST(Fields, ThePullIsMinusTheGradientOfItsPotential) {
  Attractor f;
  f.strength = 2.0;
  f.softening = 0.3;
  const Vec3 x(0.7, -0.2, 0.4);
  const double e = 1e-6;
  for (int c = 0; c < 3; ++c) {
    const Vec3 dx = e * Vec3::Unit(c);
    const double slope = (field_potential(f, x + dx) - field_potential(f, x - dx)) / (2 * e);
    EXPECT_NEAR(field_acceleration(f, x)[c], -slope, 1e-8);
  }
}

TEST(Fields, AnOrbitKeepsItsEnergyAndItsPeriod) {
  // A circular orbit of radius 1 about a pull of strength 4 (softening negligible): speed 2,
  // period pi. RK4 at h = T / 400 keeps the energy to 1e-9 and comes back to its start.
  const Scene s = parse_scene(R"({"particles": [{"position": [1, 0, 0], "velocity": [0, 0, -2]}],
      "attractors": [{"center": [0, 0, 0], "strength": 4, "softening": 1e-9}]})",
                              "orbit.json");
  Simulation sim = test::simulation(s, Method::RK4, std::numbers::pi / 400);
  const double e0 = sim.energy().total();
  EXPECT_NEAR(e0, 0.5 * 4 - 4.0, 1e-9);  // m v^2 / 2 - m S / r
  sim.advance(400);
  EXPECT_NEAR(sim.energy().total(), e0, 1e-9);
  EXPECT_LT((sim.state().x.row(0) - Eigen::RowVector3d(1, 0, 0)).norm(), 1e-6);
}

TEST(Fields, ADragInAWindTendsToTheWindsVelocity) {
  // m v' = -k (v - w): v(t) = w + (v0 - w) exp(-k t / m). m = 1, k = 2, w = (3, 0, 1), v0 = 0.
  const Scene s = parse_scene(
      R"({"particles": [{"position": [0, 0, 0]}], "drag": 2, "wind": [3, 0, 1]})", "wind.json");
  const Simulation sim = run(s, Method::RK4, 0.001, 1000);
  const Vec3 w(3, 0, 1);
  const Vec3 expected = w * (1 - std::exp(-2.0));
  EXPECT_LT((sim.state().v.row(0).transpose() - expected).norm(), 1e-10);
}

TEST(ParticleScenes, BadEmittersAndFieldsAreRefusedWithTheFieldNamed) {
  struct Case {
    std::string text;
    std::vector<std::string> says;
  };
  const std::string e = R"({"emitters": [{"position": [0, 0, 0], "rate": 10)";
  const Case cases[] = {
      {e + R"(, "max": 2000000}]})", {"/emitters/0/max", "[1, 1000000]"}},
      {e + R"(, "max": 0}]})", {"/emitters/0/max", "[1, 1000000]"}},
      {e + R"(, "direction": [0, 0, 0]}]})", {"/emitters/0/direction", "must not be zero"}},
      {e + R"(, "shape": "disc"}]})", {"/emitters/0/radius", "above 0"}},
      {e + R"(, "spread": 200}]})", {"/emitters/0/spread", "[0, 180]"}},
      {e + R"(, "lifetime": 1, "lifetime_spread": 1}]})",
       {"/emitters/0/lifetime_spread", "less than"}},
      {e + R"(, "colors": [[1, 2, 0]]}]})", {"/emitters/0/colors/0/1", "[0, 1]"}},
      {e + R"(, "burst": {"count": 50, "max": 10}}]})",
       {"/emitters/0/burst/max", "at least one burst"}},
      {e + R"(, "rte": 5}]})", {"/emitters/0/rte", "did you mean \"rate\""}},
      {R"({"emitters": [{"position": [0, 0, 0], "rate": -1}]})", {"/emitters/0/rate", "got -1"}},
      {R"({"particles": [{"position": [0, 0, 0]}], "wind": [1, 0, 0]})", {"/wind", "drag"}},
      {R"({"particles": [{"position": [0, 0, 0]}], "attractors": [{"center": [0, 0, 0]}]})",
       {"/attractors/0", "does nothing"}},
      {R"({"particles": [{"position": [0, 0, 0]}], "attractors": [{"center": [0, 0, 0], "strength": 1, "softening": 0}]})",
       {"/attractors/0/softening", "got 0"}},
  };
  for (const Case& c : cases) {
    try {
      parse_scene(c.text, "bad.json");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& error) {
      for (const std::string& part : c.says)
        EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
            << error.what() << "\n  should say: " << part;
    }
  }
}

}  // namespace
}  // namespace springlab
