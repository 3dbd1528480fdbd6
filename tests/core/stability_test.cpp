// Stability exactly where each method fails: the one-mode limits against the closed forms and
// against each method's own step, the scene analysis against dense reference solvers built here
// from the forces and the steps themselves, runs that hold just inside and fail just outside,
// and the energy audit catching an instability that never blows up.
#include "springlab/stability.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "springlab/forces.hpp"
#include "support.hpp"

namespace springlab {
namespace {

const std::vector<Method> kFixedStep = test::explicit_fixed_step();

TEST(ModeLimit, MatchesTheClosedForms) {
  const double w = 10.0;
  EXPECT_EQ(stable_step(Method::Euler, w, 0.0), 0.0);
  EXPECT_EQ(stable_step(Method::Midpoint, w, 0.0), 0.0);
  EXPECT_EQ(stable_step(Method::ModifiedEuler, w, 0.0), 0.0);
  EXPECT_NEAR(stable_step(Method::SymplecticEuler, w, 0.0), 2.0 / w, 1e-12);
  EXPECT_NEAR(stable_step(Method::Verlet, w, 0.0), 2.0 / w, 1e-12);
  EXPECT_NEAR(stable_step(Method::RK4, w, 0.0), 2.0 * std::sqrt(2.0) / w, 1e-9);
  EXPECT_TRUE(std::isinf(stable_step(Method::ImplicitEuler, w, 0.0)));
  EXPECT_TRUE(std::isnan(stable_step(Method::RK45, w, 0.0)));
  // Damped explicit Euler: stable exactly while h <= c / w^2 (k_d / k_s for a unit mass).
  for (double c : {0.5, 2.0, 5.0})
    EXPECT_NEAR(stable_step(Method::Euler, w, c), c / (w * w), 1e-12 * c / (w * w));
  // And the table's undamped limits agree with the computed ones.
  for (const MethodInfo& m : methods()) {
    if (!std::isfinite(m.undamped_limit)) continue;
    EXPECT_NEAR(stable_step(m.id, 1.0, 0.0), m.undamped_limit, 1e-9) << m.name;
  }
}

// Each closed form (Jury's conditions on the characteristic polynomial, the root of |R|^2 = 1,
// Verlet's exit through -1) against the method's own step applied to the oscillator: stable at
// every h below the limit, unstable just above it, damped or not, underdamped or overdamped.
TEST(ModeLimit, IsWhereEachMethodsOwnStepStopsBeingStable) {
  const double w = 10.0;
  for (Method m : kFixedStep)
    for (double zeta : {0.0, 0.001, 0.05, 0.3, 0.9, 1.5, 4.0})
      for (double d : {0.0, 0.15}) {
        if (d > 0.0 && m != Method::Verlet) continue;
        const MethodParameters p{.verlet_damping = d};
        const double c = 2.0 * zeta * w, h = stable_step(m, w, c, p);
        SCOPED_TRACE(std::string(method_info(m).name) + " zeta " + std::to_string(zeta) + " d " +
                     std::to_string(d));
        if (h == 0.0) {
          EXPECT_GT(amplification(m, w, c, 0.1 / w, p), 1.0);
          continue;
        }
        ASSERT_TRUE(std::isfinite(h));
        for (int k = 1; k <= 200; ++k)
          EXPECT_LE(amplification(m, w, c, h * k / 200.0 * (1 - 1e-9), p), 1.0 + 1e-9);
        EXPECT_GT(amplification(m, w, c, h * (1 + 1e-5), p), 1.0);
      }
}

TEST(ModeLimit, AmplificationFactorsAreTheKnownOnes) {
  const double w = 10.0, h = 0.05, s = (h * w) * (h * w);
  EXPECT_NEAR(amplification(Method::Euler, w, 0, h), std::sqrt(1 + s), 1e-9);
  EXPECT_NEAR(amplification(Method::Midpoint, w, 0, h), std::sqrt(1 + s * s / 4), 1e-9);
  EXPECT_NEAR(amplification(Method::ModifiedEuler, w, 0, h), std::sqrt(1 + s / 2), 1e-9);
  EXPECT_NEAR(amplification(Method::ImplicitEuler, w, 0, h), 1 / std::sqrt(1 + s), 1e-9);
  EXPECT_NEAR(amplification(Method::RK4, w, 0, 0.29), 1.19,
              0.005);  // docs/numerics.md, "The undamped oscillator"
}

// Runs `steps` steps; true if the run did not diverge (nor go numerically unstable).
bool holds(const Scene& scene, Method method, double h, int steps) {
  Simulation sim = test::simulation(scene, method, h);
  return sim.advance(steps) == steps;
}

TEST(Stability, EachLimitHoldsJustInsideAndFailsJustOutside) {
  const Scene spring = test::linear_oscillator();  // k_s = 100, m = 1: w = 10
  EXPECT_TRUE(holds(spring, Method::SymplecticEuler, 0.19, 20000));
  EXPECT_FALSE(holds(spring, Method::SymplecticEuler, 0.21, 20000));
  EXPECT_TRUE(holds(spring, Method::Verlet, 0.19, 20000));
  EXPECT_FALSE(holds(spring, Method::Verlet, 0.21, 20000));
  EXPECT_TRUE(holds(spring, Method::RK4, 0.28, 20000));
  EXPECT_FALSE(holds(spring, Method::RK4, 0.29, 20000));
  // Explicit Euler with damping: h <= k_d / k_s = 0.02.
  const Scene damped = test::linear_oscillator(100.0, 2.0);
  EXPECT_TRUE(holds(damped, Method::Euler, 0.019, 20000));
  EXPECT_FALSE(holds(damped, Method::Euler, 0.021, 20000));
  // Undamped, the never-stable methods fail at any step (here h w = 0.5).
  for (Method m : {Method::Euler, Method::Midpoint, Method::ModifiedEuler})
    EXPECT_FALSE(holds(spring, m, 0.05, 20000)) << method_info(m).name;
}

// The damped Verlet: the restart step said 0.1844 s; the recurrence Verlet runs holds at
// 0.1607 s and diverges at 0.1672 s (its limit, the root of h^2 k + 4 h c = 4, is 0.16396 s).
TEST(Stability, DampedVerletsLimitIsItsRecurrences) {
  const Scene damped = test::shipped("damped-spring");
  const StabilityAnalysis a(damped.model, damped.state);
  EXPECT_NEAR(a.limit(Method::Verlet).h, (-8.0 + std::sqrt(64.0 + 1600.0)) / 200.0, 1e-12);
  const Scene linear = test::linear_oscillator(100.0, 2.0);
  EXPECT_TRUE(holds(linear, Method::Verlet, 0.1607, 20000));
  EXPECT_FALSE(holds(linear, Method::Verlet, 0.1672, 20000));
}

TEST(Stability, DivergenceReportsStepTimeMethodAndLimit) {
  const Scene spring = test::linear_oscillator();
  Simulation sim = test::simulation(spring, Method::RK4, 0.29);
  sim.advance(1000);
  ASSERT_TRUE(sim.diverged());
  const Divergence& d = *sim.explain_divergence();
  EXPECT_EQ(d.method, Method::RK4);
  EXPECT_DOUBLE_EQ(d.h, 0.29);
  EXPECT_NEAR(d.w_max, 10.0, 1e-6);
  EXPECT_NEAR(d.stable_h, 0.2828427, 1e-6);
  EXPECT_GT(d.step, 10);
  EXPECT_TRUE(all_finite(sim.state()));  // the last good state is kept
  const std::string message = d.message();
  for (const char* part : {"rk4", "h = 0.29", "stable up to h = 0.2828", "step", "10 rad/s"})
    EXPECT_NE(message.find(part), std::string::npos) << message;
}

// On `spring` (rest length 1) RK4 at h = 0.29 leaves the physical motion, but the double well
// about the anchor stops the growth: nothing becomes infinite. Without the audit it goes on for
// ever at ten times its energy; with it, the run is reported numerically unstable.
TEST(Stability, TheAuditCatchesAnInstabilityThatSaturates) {
  const Scene spring = test::shipped("spring");
  SimulationSettings s;
  s.method = Method::RK4;
  s.dt = 0.29;
  s.audit_fraction = 0.0;
  Simulation unaudited(spring.model, spring.state, s);
  double highest = 0.0, nearest = 1e9;
  for (int k = 0; k < 2000 && unaudited.step(); ++k) {
    highest = std::max(highest, unaudited.energy().total());
    nearest = std::min(nearest, std::abs(unaudited.state().x(1, 0)));
  }
  EXPECT_FALSE(unaudited.diverged());
  EXPECT_GT(highest, 10 * 12.5);
  EXPECT_LT(nearest, 0.5);  // the exact motion never comes closer than 0.5

  s.audit_fraction = kAuditFraction;
  Simulation audited(spring.model, spring.state, s);
  audited.advance(2000);
  ASSERT_TRUE(audited.diverged());
  const Divergence& d = *audited.divergence();
  EXPECT_TRUE(d.unstable);
  // Caught while it grows (x1.42 a step at first: the energy is 10 times its start by step 7),
  // long before the bounded buzz: within the audit's first four windows (8 checks each), from a
  // low before the two windows that rose.
  EXPECT_LE(d.step, 4 * 8) << d.message();
  EXPECT_LE(d.audit.low_step, d.step - 8);
  EXPECT_GT(d.audit.rise, 10.0 * d.audit.allowed) << d.message();
  EXPECT_NE(d.message().find("numerically unstable"), std::string::npos) << d.message();
}

// The case: a 100-node hanging rope under explicit Euler past its sideways modes' limit
// (2.1e-5 s) gains tens of joules from nothing and then buzzes near the pin, bounded; the
// divergence test alone never fires within its 10 s, the audit does. Just inside the limit (0.9
// of it) the rope holds, audited, for the same 10 s.
TEST(Stability, TheAuditCatchesTheBuzzingRope) {
  const Scene rope = test::shipped("rope", {"rope.nodes=100"});
  const StabilityAnalysis a(rope.model, rope.state);
  const StabilityLimit& euler = a.limit(Method::Euler);
  ASSERT_TRUE(euler.exact);
  EXPECT_NEAR(euler.h, 2.097e-5, 0.001e-5);  // the old estimate (highest mode only) said 1.1e-4
  const auto steps = [](double h) { return static_cast<std::int64_t>(std::ceil(10.0 / h)); };
  SimulationSettings s;
  s.method = Method::Euler;
  s.dt = 9.0e-5;
  s.audit_fraction = 0.0;
  Simulation unaudited(rope.model, rope.state, s);
  EXPECT_EQ(unaudited.advance(steps(9.0e-5)), steps(9.0e-5))
      << "the divergence test catches it: no test of the audit";
  Simulation past = test::simulation(rope, Method::Euler, 9.0e-5);
  past.advance(steps(9.0e-5));
  ASSERT_TRUE(past.diverged());
  EXPECT_TRUE(past.divergence()->unstable) << past.divergence()->message();
  Simulation inside = test::simulation(rope, Method::Euler, 0.9 * euler.h);
  EXPECT_EQ(inside.advance(steps(0.9 * euler.h)), steps(0.9 * euler.h))
      << (inside.diverged() ? inside.divergence()->message() : "");
}

TEST(Stability, ImplicitEulerHoldsWhereEveryExplicitMethodDiverges) {
  const Scene stiff = test::shipped("stiff");
  Simulation implicit = test::simulation(stiff, Method::ImplicitEuler, stiff.dt);
  EXPECT_GT(stiff.dt * implicit.stability().w_max(), 10.0);
  EXPECT_EQ(implicit.advance(600), 600);  // 10 s
  for (Method m : kFixedStep) EXPECT_FALSE(holds(stiff, m, stiff.dt, 600)) << method_info(m).name;
}

}  // namespace
}  // namespace springlab

// ---- The analysis against dense references ------------------------------------------------------

namespace springlab {
namespace {

// The free coordinates of a scene's particles, x then v of each, and the finite-difference
// Jacobian of a map of them: the references below are built from the forces and the steps
// themselves, not from the analysis's own matrices.
struct Coordinates {
  std::vector<int> free;
  explicit Coordinates(const Model& m) {
    for (int i = 0; i < m.particle_count(); ++i)
      if (!m.pinned(i)) free.push_back(i);
  }
  int n() const { return 3 * static_cast<int>(free.size()); }
};

// A = [[0, I], [da/dx, da/dv]] at a state, by central differences of the accelerations.
Eigen::MatrixXd first_order_system(const Model& model, const State& at) {
  const Coordinates q(model);
  const int n = q.n();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  Workspace ws;
  Points plus, minus;
  const double eps = 1e-6;
  for (int k = 0; k < 2 * n; ++k) {
    State p = at, m = at;
    const int i = q.free[(k % n) / 3], c = k % 3;
    (k < n ? p.x : p.v)(i, c) += eps;
    (k < n ? m.x : m.v)(i, c) -= eps;
    accelerations(model, p.x, p.v, plus, ws);
    accelerations(model, m.x, m.v, minus, ws);
    for (int j = 0; j < n; ++j)
      A(n + j, k) = (plus(q.free[j / 3], j % 3) - minus(q.free[j / 3], j % 3)) / (2 * eps);
  }
  return A;
}

std::vector<std::complex<double>> sorted(std::vector<std::complex<double>> v) {
  std::sort(v.begin(), v.end(), [](auto a, auto b) {
    return std::abs(a.imag() - b.imag()) > 1e-9 * (std::abs(a) + 1) ? a.imag() < b.imag()
                                                                    : a.real() < b.real();
  });
  return v;
}

// On a small chain hanging in tension (every spring stretched, so the definite Jacobians are
// the exact ones), the analysis's eigenvalues are those of A from the forces.
TEST(Analysis, EigenvaluesEqualADenseReferenceSolvers) {
  const Scene chain = test::shipped("rope", {"rope.nodes=12"});
  const StabilityAnalysis a(chain.model, chain.state);
  ASSERT_TRUE(a.dense());
  const State rest = equilibrium(chain.model, chain.state);
  const Eigen::VectorXcd reference =
      Eigen::EigenSolver<Eigen::MatrixXd>(first_order_system(chain.model, rest), false)
          .eigenvalues();
  std::vector<std::complex<double>> ref(reference.begin(), reference.end());
  ref.erase(std::remove_if(ref.begin(), ref.end(),
                           [&](auto z) { return std::abs(z) <= 1e-6 * a.w_bound(); }),
            ref.end());
  const auto mine = sorted(a.eigenvalues());
  ref = sorted(ref);
  ASSERT_EQ(mine.size(), ref.size());
  for (std::size_t k = 0; k < ref.size(); ++k)
    EXPECT_LT(std::abs(mine[k] - ref[k]), 1e-6 * std::abs(ref[k])) << k;
}

// docs/numerics.md's oscillator, at its equilibrium (rest length): the analysis gives the closed
// forms to 1e-6.
TEST(Analysis, TheSingleSpringHasTheClosedFormLimits) {
  const double w = 10.0;
  const StabilityAnalysis undamped(test::shipped("spring").model, test::shipped("spring").state);
  EXPECT_EQ(undamped.limit(Method::Euler).h, 0.0);
  EXPECT_EQ(undamped.limit(Method::Midpoint).h, 0.0);
  EXPECT_EQ(undamped.limit(Method::ModifiedEuler).h, 0.0);
  EXPECT_NEAR(undamped.limit(Method::SymplecticEuler).h, 2.0 / w, 1e-6 * 2.0 / w);
  EXPECT_NEAR(undamped.limit(Method::Verlet).h, 2.0 / w, 1e-6 * 2.0 / w);
  EXPECT_NEAR(undamped.limit(Method::RK4).h, 2.0 * std::sqrt(2.0) / w, 1e-6 * 2.8 / w);
  EXPECT_NEAR(undamped.w_max(), w, 1e-9);

  const Scene damped = test::shipped("damped-spring");  // k_d = 2: c = 2
  const StabilityAnalysis a(damped.model, damped.state);
  const double c = 2.0;
  EXPECT_NEAR(a.limit(Method::Euler).h, c / (w * w), 1e-6 * 0.02);                // k_d / k_s
  EXPECT_NEAR(a.limit(Method::ModifiedEuler).h, 2.0 * c / (w * w), 1e-6 * 0.04);  // 2 k_d / k_s
  EXPECT_NEAR(a.limit(Method::SymplecticEuler).h, 4.0 / (c + std::sqrt(c * c + 4 * w * w)),
              1e-6 * 0.18);
  EXPECT_NEAR(a.limit(Method::Verlet).h, 8.0 / (4 * c + std::sqrt(16 * c * c + 16 * w * w)),
              1e-6 * 0.16);
  for (Method m : kFixedStep) {
    EXPECT_TRUE(a.limit(m).exact) << method_info(m).name;
    ASSERT_TRUE(a.limit(m).mode) << method_info(m).name;
    EXPECT_NEAR(a.limit(m).mode->w, w, 1e-6);
    EXPECT_NEAR(a.limit(m).mode->damping_ratio(), c / (2 * w), 1e-6);
  }
  // RK4 and midpoint from the eigenvalue -c/2 + i sqrt(w^2 - c^2/4): |R(h lambda)| = 1 there.
  const std::complex<double> lambda(-c / 2, std::sqrt(w * w - c * c / 4));
  for (Method m : {Method::Midpoint, Method::RK4}) {
    const double h = a.limit(m).h;
    const std::complex<double> z = h * lambda;
    const std::complex<double> R =
        m == Method::RK4 ? 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0
                         : 1.0 + z + z * z / 2.0;
    EXPECT_NEAR(std::abs(R), 1.0, 1e-9) << method_info(m).name;
  }
}

// The large scenes' path (the joint numerical range, Lanczos) on scenes small enough to solve
// densely: equal where it says exact, never above where it gives a bound.
TEST(Analysis, TheLargeScenePathAgreesWithTheDenseOne) {
  for (const auto& [name, overrides] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"chain", {}},
           {"rope", {"rope.nodes=64"}},
           {"stiff", {}},
           {"cloth", {"cloth.width=8", "cloth.height=8"}}}) {
    const Scene s = test::shipped(name, overrides);
    const StabilityAnalysis dense(s.model, s.state), large(s.model, s.state, 0);
    ASSERT_TRUE(dense.dense() && !large.dense()) << name;
    EXPECT_NEAR(large.w_max(), dense.w_max(), 1e-8 * dense.w_max()) << name;
    for (Method m : kFixedStep) {
      const StabilityLimit &d = dense.limit(m), &l = large.limit(m);
      SCOPED_TRACE(name + " " + method_info(m).name);
      if (d.exact && l.exact)
        EXPECT_NEAR(l.h, d.h, 1e-6 * d.h);
      else
        EXPECT_LE(l.h, d.h * (1 + 1e-9));
    }
  }
}

// Symplectic Euler and Verlet: the limit from the definiteness test is where the spectral radius
// of the step itself (finite differences of the method's own step, Verlet with the history it
// keeps) crosses 1, on a chain and a small cloth at their equilibria.
double step_radius(Method method, const Model& model, const State& rest, double h) {
  const Coordinates q(model);
  const int n = q.n();
  // State of the recurrence: x and v (symplectic Euler), or x, x_prev and a (Verlet).
  const int blocks = method == Method::Verlet ? 3 : 2;
  Workspace base;
  State out = rest;
  if (method == Method::Verlet) step(method, model, rest, out, h, {}, base);  // fills the history
  const auto apply = [&](const Eigen::VectorXd& z) {
    State in = method == Method::Verlet ? out : rest;
    Workspace ws = Workspace();
    if (method == Method::Verlet) {
      ws.x_prev = base.x_prev;
      ws.a_now = base.a_now;
      ws.verlet_ready = true;
      ws.verlet_h = h;
    }
    for (int k = 0; k < n; ++k) {
      const int i = q.free[k / 3], c = k % 3;
      in.x(i, c) += z[k];
      if (method == Method::Verlet) {
        ws.x_prev(i, c) += z[n + k];
        ws.a_now(i, c) += z[2 * n + k];
      } else {
        in.v(i, c) += z[n + k];
      }
    }
    State next = in;
    step(method, model, in, next, h, {}, ws);
    Eigen::VectorXd y(blocks * n);
    for (int k = 0; k < n; ++k) {
      const int i = q.free[k / 3], c = k % 3;
      y[k] = next.x(i, c);
      y[n + k] = method == Method::Verlet ? ws.x_prev(i, c) : next.v(i, c);
      if (method == Method::Verlet) y[2 * n + k] = ws.a_now(i, c);
    }
    return y;
  };
  Eigen::MatrixXd J(blocks * n, blocks * n);
  const double eps = 1e-7;
  for (int k = 0; k < blocks * n; ++k) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(blocks * n);
    e[k] = eps;
    J.col(k) = (apply(e) - apply(-e)) / (2 * eps);
  }
  double rho = 0.0;
  const Eigen::VectorXcd mus = Eigen::EigenSolver<Eigen::MatrixXd>(J, false).eigenvalues();
  for (auto mu : mus)
    if (std::abs(mu - 1.0) > 1e-5)
      rho = std::max(rho, std::abs(mu));  // neutral rigid motions sit at 1
  return rho;
}

TEST(Analysis, PartitionedLimitsAreWhereTheStepsRadiusCrossesOne) {
  for (const auto& [name, overrides] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"rope", {"rope.nodes=8"}}, {"cloth", {"cloth.width=4", "cloth.height=4"}}}) {
    const Scene s = test::shipped(name, overrides);
    const StabilityAnalysis a(s.model, s.state);
    const State rest = equilibrium(s.model, s.state);
    for (Method m : {Method::SymplecticEuler, Method::Verlet}) {
      const double h = a.limit(m).h;
      SCOPED_TRACE(name + " " + method_info(m).name);
      EXPECT_LE(step_radius(m, s.model, rest, 0.999 * h), 1.0 + 1e-6);
      EXPECT_GT(step_radius(m, s.model, rest, 1.001 * h), 1.0 + 1e-6);
    }
  }
}

// The rope: its sideways modes stretch no spring, so only the drag damps them
// (c = k_drag / m = 18.75 /s), and the fastest of them sets explicit Euler's limit, not the
// highest mode. At the limit, h = c / w^2 for that mode, and the mode moves across the rope.
TEST(Analysis, TheLongRopeIsLimitedByItsSidewaysModes) {
  const Scene rope = test::shipped("rope", {"rope.nodes=1000"});
  const StabilityAnalysis a(rope.model, rope.state);
  const StabilityLimit& euler = a.limit(Method::Euler);
  ASSERT_TRUE(euler.mode);
  const double drag_rate = rope.model.drag * rope.model.inv_mass[1];
  EXPECT_NEAR(euler.mode->c, drag_rate, 1e-6 * drag_rate);
  EXPECT_NEAR(euler.h, euler.mode->c / (euler.mode->w * euler.mode->w), 1e-9 * euler.h);
  EXPECT_LT(euler.h, 0.2 * a.limit(Method::Midpoint).h);
  EXPECT_GT(euler.mode->w, 2500.0);  // about 2 sqrt(T / (m l)) with T the rope's weight at the pin
  EXPECT_LT(euler.mode->w, 3500.0);
  // Across the rope: it hangs along -y, the mode moves in x and z.
  const Points& shape = euler.mode->shape;
  EXPECT_LT(shape.col(1).norm(), 1e-6 * shape.norm());
}

// The balance holds to its stated tolerance (stability.hpp), the forces summed here from the
// springs and the weights:
// - a 48 x 48 cloth (6,900 free coordinates; a factorisation would cost 1.9e8) by relaxation
//   alone, to 4e-2 of a particle's weight;
// - ropes of 200, 1400 and 7000 nodes (a factorisation of a path's band is cheap) by Newton's
//   method, to 1e-8 of the springs' force at 1 % strain. The 7000-node rope's weights are 1/16
//   of the 1e-3 of that force which once counted as balanced: it stayed flat. Hanging, its pin
//   holds its whole weight, and its lowest spring that of the last particle.
// The cloth's balance is the same to the bit on one thread and on two (its force pass is shared
// between them).
TEST(Equilibrium, BalancesTheForcesToItsStatedTolerance) {
  enum Against { Weight, Strain };
  for (const auto& [name, overrides, tolerance, against] :
       std::vector<std::tuple<std::string, std::vector<std::string>, double, Against>>{
           {"cloth", {"cloth.width=48", "cloth.height=48"}, 4e-2, Weight},
           {"rope", {"rope.nodes=200"}, 1e-8, Strain},
           {"rope", {"rope.nodes=1400"}, 1e-8, Strain},
           {"rope", {"rope.nodes=7000"}, 1e-8, Strain}}) {
    const Scene scene = test::shipped(name, overrides);
    const Model& m = scene.model;
    SCOPED_TRACE(name + " of " + std::to_string(m.particle_count()));
    const State rest = equilibrium(m, scene.state);
    ASSERT_TRUE(rest.x.allFinite());
    double strain = 0.0, weight = 0.0, total_weight = 0.0;
    for (int s = 0; s < m.spring_count(); ++s)
      strain = std::max(strain, 0.01 * m.ks(s) * std::max(m.rest_length[s], 1e-3));
    Points f = Points::Zero(m.particle_count(), 3);
    for (int i = 0; i < m.particle_count(); ++i) {
      f.row(i) = m.mass[i] * m.gravity.transpose();  // every particle of these is held
      if (m.pinned(i)) continue;
      weight = std::max(weight, m.mass[i] * m.gravity.norm());
      total_weight += m.mass[i] * m.gravity.norm();
    }
    std::vector<double> tension(m.spring_count());
    for (int s = 0; s < m.spring_count(); ++s) {
      const int a = m.spring_a[s], b = m.spring_b[s];
      const Eigen::Vector3d d = rest.x.row(b) - rest.x.row(a);
      tension[s] = m.ks(s) * (d.norm() - m.rest_length[s]);
      const Eigen::Vector3d pull = tension[s] * d.normalized();
      f.row(a) += pull.transpose();
      f.row(b) -= pull.transpose();
    }
    double largest = 0.0;
    for (int i = 0; i < m.particle_count(); ++i)
      if (!m.pinned(i)) largest = std::max(largest, f.row(i).cwiseAbs().maxCoeff());
    EXPECT_LE(largest, tolerance * (against == Weight ? weight : strain));
    EXPECT_GT(largest, 0.0);
    EXPECT_EQ(rest.v.norm(), 0.0);
    if (name == "rope") {  // pinned at its first node, springs in order along it
      EXPECT_NEAR(tension.front(), total_weight, 1e-6 * total_weight);
      EXPECT_NEAR(tension.back(), weight, 1e-3 * weight);
    }
    if (name == "cloth") {
      set_thread_count(1);
      const std::uint64_t one = state_hash(equilibrium(m, scene.state));
      set_thread_count(2);
      const std::uint64_t two = state_hash(equilibrium(m, scene.state));
      set_thread_count(0);
      EXPECT_EQ(one, two);
      EXPECT_EQ(one, state_hash(rest));
    }
  }
}

// With no weight to hold (here no gravity), the tensions are whatever the pins stretch the springs
// to: a 32 x 32 cloth (relaxation alone, a factorisation would cost 4.3e7) stretched by 1 % between
// its pinned corners balances to 1e-5 of its springs' force at 1 % strain, not to the 4e-2 a
// weighed cloth relaxes to.
TEST(Equilibrium, WithNoWeightBalancesTheSpringsToTheirOwnScale) {
  Scene scene = test::shipped("cloth", {"cloth.width=32", "cloth.height=32", "gravity=[0,0,0]"});
  const Model& m = scene.model;
  const Eigen::RowVector3d centre = scene.state.x.colwise().mean();
  scene.state.x = ((scene.state.x.rowwise() - centre) * 1.01).rowwise() + centre;
  const State rest = equilibrium(m, scene.state);
  ASSERT_TRUE(rest.x.allFinite());
  double strain = 0.0;
  for (int s = 0; s < m.spring_count(); ++s)
    strain = std::max(strain, 0.01 * m.ks(s) * m.rest_length[s]);
  const auto largest_force = [&](const Points& x) {  // on a free particle, from the springs
    Points f = Points::Zero(m.particle_count(), 3);
    for (int s = 0; s < m.spring_count(); ++s) {
      const int a = m.spring_a[s], b = m.spring_b[s];
      const Eigen::Vector3d d = x.row(b) - x.row(a);
      const Eigen::Vector3d pull = m.ks(s) * (d.norm() - m.rest_length[s]) * d.normalized();
      f.row(a) += pull.transpose();
      f.row(b) -= pull.transpose();
    }
    double largest = 0.0;
    for (int i = 0; i < m.particle_count(); ++i)
      if (!m.pinned(i)) largest = std::max(largest, f.row(i).cwiseAbs().maxCoeff());
    return largest;
  };
  EXPECT_LE(largest_force(rest.x), 1e-5 * strain);
  const double start = largest_force(scene.state.x);
  EXPECT_GT(start, 4e-2 * strain);  // stretched: far from balanced at the start
}

TEST(Analysis, ASceneWithNoOscillatingModesSaysSo) {
  const StabilityAnalysis fountain(test::shipped("fountain").model,
                                   test::shipped("fountain").state);
  EXPECT_FALSE(fountain.oscillates());
  EXPECT_EQ(fountain.no_modes_reason(), "no springs");
  Scene pinned = test::shipped("chain");
  for (int i = 0; i < pinned.model.particle_count(); ++i) set_pinned(pinned.model, i, true);
  const StabilityAnalysis all(pinned.model, pinned.state);
  EXPECT_FALSE(all.oscillates());
  EXPECT_EQ(all.no_modes_reason(), "every particle is pinned");
  for (const StabilityAnalysis* a : {&fountain, &all})
    for (Method m : kFixedStep) EXPECT_FALSE(std::isnan(a->limit(m).h)) << method_info(m).name;
  // Free particles with drag and no springs: only the drag's first-order decay, at k_drag / m,
  // which explicit Euler overshoots past h = 2 m / k_drag.
  Scene dust;
  for (int i = 0; i < 3; ++i) add_particle(dust.model, 2.0, false);
  dust.model.drag = 0.5;
  finalize(dust.model);
  dust.state.resize(3);
  dust.state.x.setRandom();
  dust.state.v.setZero();
  const StabilityAnalysis decay(dust.model, dust.state);
  EXPECT_EQ(decay.no_modes_reason(), "no springs");
  EXPECT_NEAR(decay.limit(Method::Euler).h, 2.0 * 2.0 / 0.5, 1e-12);
  EXPECT_NEAR(decay.limit(Method::SymplecticEuler).h, 2.0 * 2.0 / 0.5, 1e-12);
  // Coincident ends: no direction, no stiffness.
  const Scene pair = test::coincident_pair(true, 100.0, 0.5);
  const StabilityAnalysis coincident(pair.model, pair.state);
  EXPECT_FALSE(coincident.oscillates());
}

// compare's measured stable step comes from runs: on the damped spring each method's runs
// turn unstable within the measurement's resolution of the analysis's limit.
TEST(Analysis, RunsFindTheAnalysisLimits) {
  const Scene s = test::shipped("damped-spring");
  const StabilityAnalysis a(s.model, s.state);
  for (Method m : kFixedStep) {
    const StabilityLimit& limit = a.limit(m);
    const MeasuredLimit measured = measured_limit(m, s.model, s.state, limit, a.w_max());
    SCOPED_TRACE(method_info(m).name);
    EXPECT_LE(measured.resolution, 0.01);
    EXPECT_NEAR(measured.h, limit.h, (measured.resolution + 1e-3) * limit.h);
  }
  EXPECT_TRUE(std::isinf(measured_limit(Method::ImplicitEuler, s.model, s.state,
                                        a.limit(Method::ImplicitEuler), a.w_max())
                             .h));
}

// The budget bounds the probes upwards too. Implicit Euler on a 16 x 16 cloth with a budget of
// 1e5 particle- and spring-steps, less than one probe's 200 steps: the measurement stops after
// the first probe that held and says "at least", where it had run 10 probes up to h w = 1000 and
// said "always". Within its budget it still finds it stable at any step.
TEST(Analysis, TheBudgetBoundsTheProbesOfAMethodStableAtAnyStep) {
  const Scene cloth = test::shipped("cloth", {"cloth.width=16", "cloth.height=16"});
  const StabilityAnalysis a(cloth.model, cloth.state);
  const MeasuredLimit spent = measured_limit(Method::ImplicitEuler, cloth.model, cloth.state,
                                             a.limit(Method::ImplicitEuler), a.w_max(), {}, 1e5);
  EXPECT_TRUE(spent.at_least);
  EXPECT_TRUE(std::isfinite(spent.h));
  EXPECT_GE(spent.h * a.w_max(), 1.0 - 1e-12);  // the first probe, at h w = 1, held
  EXPECT_TRUE(std::isinf(spent.resolution));
  // Within its budget, the same method on the damped spring: probed to h w = 1000, "always".
  const Scene spring = test::shipped("damped-spring");
  const StabilityAnalysis b(spring.model, spring.state);
  const MeasuredLimit always = measured_limit(Method::ImplicitEuler, spring.model, spring.state,
                                              b.limit(Method::ImplicitEuler), b.w_max());
  EXPECT_FALSE(always.at_least);
  EXPECT_TRUE(std::isinf(always.h));
}

// The quick bound a lane starts with while the analysis runs (quick_limit) is safe: never above
// the exact limit on the shipped scenes with springs, for every fixed-step method; and it tells
// (is above 0) for the methods stable without damping. How far below: printed.
TEST(QuickLimit, IsNeverAboveTheLimit) {
  for (const char* name :
       {"spring", "damped-spring", "rope", "chain", "cloth", "cloth-sphere", "jelly", "stiff"}) {
    const Scene scene = test::shipped(name);
    const StabilityAnalysis a(scene.model, scene.state);
    std::printf("  %-14s", name);
    for (Method m : kFixedStep) {
      const StabilityLimit& limit = a.limit(m);
      const StabilityLimit quick = quick_limit(m, scene.model, scene.state);
      SCOPED_TRACE(std::string(name) + ", " + method_info(m).name + ": " + describe(limit));
      EXPECT_FALSE(quick.exact);
      if (limit.exact) {
        EXPECT_LE(quick.h, limit.h * (1.0 + 1e-12));
      }
      if (m == Method::SymplecticEuler || m == Method::Verlet || m == Method::RK4) {
        EXPECT_GT(quick.h, 0.0);
      }
      if (limit.h > 0.0 && std::isfinite(limit.h))
        std::printf(" %s %.2f", method_info(m).name, quick.h / limit.h);
    }
    std::printf("\n");
  }
  const Scene spring = test::shipped("spring");
  EXPECT_TRUE(std::isinf(quick_limit(Method::ImplicitEuler, spring.model, spring.state).h));
  EXPECT_TRUE(std::isnan(quick_limit(Method::RK45, spring.model, spring.state).h));
}

// An analysis no longer wanted stops when told to: set before it starts, it does nothing; set
// from another thread while a 64 x 64 cloth's runs (seconds: its relaxation, its factorisation,
// its Lanczos runs), it ends without finishing, marked cancelled. The same analysis left alone
// finishes.
TEST(Analysis, StopsWhenCancelled) {
  const Scene cloth = test::shipped("cloth", {"cloth.width=64", "cloth.height=64"});
  std::atomic<bool> stop{true};
  EXPECT_TRUE(StabilityAnalysis(cloth.model, cloth.state, kDenseDofs, &stop).cancelled());
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "no threads in this build to cancel from";
#endif
  stop = false;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    stop = true;
  });
  const StabilityAnalysis stopped(cloth.model, cloth.state, kDenseDofs, &stop);
  canceller.join();
  EXPECT_TRUE(stopped.cancelled());
  const Scene small = test::shipped("cloth");
  std::atomic<bool> never{false};
  const StabilityAnalysis whole(small.model, small.state, kDenseDofs, &never);
  EXPECT_FALSE(whole.cancelled());
  EXPECT_GT(whole.limit(Method::SymplecticEuler).h, 0.0);
}

}  // namespace
}  // namespace springlab
