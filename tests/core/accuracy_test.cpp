// Accuracy on the reference spring against its exact solution: every fixed-step method's order
// measured by halving the step (docs/numerics.md, "Accuracy and cost": within 0.2), and the
// adaptive methods' error falling with their tolerance, with their step counts checked against what
// the controllers must do.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"

namespace springlab {
namespace {

TEST(Exact, SolutionSatisfiesTheEquationOfMotion) {
  for (double kd : {0.0, 2.0, 20.0, 30.0}) {  // undamped, underdamped, critical, overdamped
    const Scene scene = test::oscillator(100.0, kd);
    const auto exact = ExactOscillator::detect(scene.model, scene.state);
    ASSERT_TRUE(exact) << kd;
    EXPECT_NEAR(exact->at(0).x(1, 0), 1.5, 1e-15);
    for (double t : {0.1, 0.37, 1.0, 2.5}) {
      // x'' = -100 (x - 1) - kd x', by central differences.
      const double e = 1e-4;
      const double x0 = exact->at(t - e).x(1, 0), x1 = exact->at(t).x(1, 0),
                   x2 = exact->at(t + e).x(1, 0);
      const double acceleration = (x2 - 2 * x1 + x0) / (e * e);
      const double velocity = exact->at(t).v(1, 0);
      EXPECT_NEAR((x2 - x0) / (2 * e), velocity, 1e-6);
      EXPECT_NEAR(acceleration, -100.0 * (x1 - 1.0) - kd * velocity, 1e-4) << kd << " " << t;
    }
  }
  // The reference scene is exactly x(t) = 1 + 0.5 cos(10 t).
  const Scene spring = test::shipped("spring");
  const auto exact = ExactOscillator::detect(spring.model, spring.state);
  for (double t : {0.0, 0.3, 1.7, 9.9})
    EXPECT_NEAR(exact->at(t).x(1, 0), 1 + 0.5 * std::cos(10 * t), 1e-14);
}

// Every fixed-step row of the table, its order measured by halving from a step in the
// asymptotic range and above round-off: (h w)^p = 1e-2 on the spring (w = 10), so that the
// leading error term is the same size whatever the order (explicit Euler 1e-3 s, RK4 0.032 s).
double coarse_step(Method method) {
  return std::pow(1e-2, 1.0 / method_info(method).order) / 10.0;
}

class Order : public ::testing::TestWithParam<Method> {};

TEST_P(Order, MatchesTheTableWithinTwoTenths) {
  const Method method = GetParam();
  const double h = coarse_step(method);
  const Scene scene = test::shipped("spring");
  const double coarse = test::error_against_exact(scene, method, h, 1.0);
  const double fine = test::error_against_exact(scene, method, h / 2, 1.0);
  const double finer = test::error_against_exact(scene, method, h / 4, 1.0);
  const double order1 = std::log2(coarse / fine), order2 = std::log2(fine / finer);
  const int expected = method_info(method).order;
  EXPECT_NEAR(order1, expected, 0.2)
      << method_info(method).name << " errors " << coarse << " " << fine;
  EXPECT_NEAR(order2, expected, 0.2)
      << method_info(method).name << " errors " << fine << " " << finer;
}

INSTANTIATE_TEST_SUITE_P(Methods, Order, ::testing::ValuesIn(test::fixed_step()),
                         [](const auto& info) {
                           std::string name = method_info(info.param).name;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(Order, DampedSpringToo) {
  // With damping the velocity matters in the force: every fixed-step method's order holds all the
  // same, over two halvings (each inside its damped limit: explicit Euler's is k_d / k_s = 0.02 s).
  const Scene scene = test::oscillator(100.0, 2.0);
  for (Method method : test::fixed_step()) {
    const double h =
        std::min(coarse_step(method), 0.02);  // inside explicit Euler's damped limit, 0.02 s
    const double coarse = test::error_against_exact(scene, method, h, 1.0);
    const double fine = test::error_against_exact(scene, method, h / 2, 1.0);
    const double finer = test::error_against_exact(scene, method, h / 4, 1.0);
    const int order = method_info(method).order;
    EXPECT_NEAR(std::log2(coarse / fine), order, 0.2)
        << method_info(method).name << " " << coarse << " " << fine;
    EXPECT_NEAR(std::log2(fine / finer), order, 0.2)
        << method_info(method).name << " " << fine << " " << finer;
  }
}

TEST(Adaptive, ErrorFallsAsTheToleranceTightens) {
  // Outer steps of 0.25 s, so that the controller, not the step, sets the internal steps.
  const Scene scene = test::shipped("spring");
  for (Method method : {Method::AdaptiveEuler, Method::RK45}) {
    double previous = std::numeric_limits<double>::infinity();
    for (double tol : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const double error = test::error_against_exact(scene, method, 0.25, 1.0, tol);
      EXPECT_LT(error, previous) << method_info(method).name << " tol " << tol;
      previous = error;
    }
    EXPECT_LT(previous, method == Method::RK45 ? 1e-5 : 2e-2);
  }
}

TEST(Adaptive, EulerStepDoublingCountsWhatTheNotesPrescribe) {
  // From rest at x = 1.5 (|a| = 50), the step-doubling error of a try of size T is exactly
  // T^2 |a| / 4. With tolerance 1e-4 and h = 0.01: T = 0.01 (err 1.25e-3) and 0.005 (3.1e-4)
  // are rejected, T = 0.0025 (7.8e-5, not below tol / 8) is accepted and kept: 4 steps.
  Scene scene = test::shipped("spring");
  SimulationSettings s;
  s.method = Method::AdaptiveEuler;
  s.dt = 0.01;
  s.step.tolerance = 1e-4;
  Simulation sim(scene.model, scene.state, s);
  ASSERT_TRUE(sim.step());
  EXPECT_EQ(sim.counters().rejected, 2);
  EXPECT_EQ(sim.counters().accepted, 4);
  // Two force evaluations per accepted step, none for a rejected try.
  EXPECT_EQ(sim.counters().force_evals, 8);
  sim.advance(99);
  EXPECT_EQ(sim.counters().force_evals, 2 * sim.counters().accepted);
}

TEST(Adaptive, DormandPrinceCountsSixEvaluationsPerTry) {
  Scene scene = test::shipped("spring");
  SimulationSettings s;
  s.method = Method::RK45;
  s.dt = 0.01;
  s.step.tolerance = 1e-9;
  Simulation sim(scene.model, scene.state, s);
  sim.advance(300);
  const Counters& c = sim.counters();
  EXPECT_GT(c.accepted, 300);  // a tight tolerance needs steps below dt
  // One evaluation to start, then six per try thanks to first-same-as-last.
  EXPECT_EQ(c.force_evals, 1 + 6 * (c.accepted + c.rejected));
}

TEST(Adaptive, StepFloorEndsARunThatCannotMeetItsTolerance) {
  // A tolerance far below what doubles can express: the step would shrink forever.
  Scene scene = test::shipped("spring");
  SimulationSettings s;
  s.method = Method::AdaptiveEuler;
  s.dt = 0.01;
  s.step.tolerance = 1e-30;
  Simulation sim(scene.model, scene.state, s);
  EXPECT_FALSE(sim.step());
  ASSERT_TRUE(sim.diverged());
  EXPECT_NE(sim.divergence()->reason.find("loosen --tol"), std::string::npos);
  EXPECT_TRUE(all_finite(sim.state()));
}

}  // namespace
}  // namespace springlab
