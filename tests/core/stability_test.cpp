// Stability exactly where NUMERICS.md says each method fails: the computed limits against the
// closed forms, runs that hold just inside and diverge just outside, and implicit Euler holding
// where every explicit method diverges.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "springlab/spring_kernel.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

TEST(StableStep, MatchesTheClosedForms) {
  const double w = 10.0;
  EXPECT_EQ(stable_step(Method::Euler, w, 0.0), 0.0);
  EXPECT_EQ(stable_step(Method::Midpoint, w, 0.0), 0.0);
  EXPECT_EQ(stable_step(Method::ModifiedEuler, w, 0.0), 0.0);
  EXPECT_NEAR(stable_step(Method::SymplecticEuler, w, 0.0), 2.0 / w, 1e-9);
  EXPECT_NEAR(stable_step(Method::Verlet, w, 0.0), 2.0 / w, 1e-9);
  EXPECT_NEAR(stable_step(Method::RK4, w, 0.0), 2.0 * std::sqrt(2.0) / w, 1e-9);
  EXPECT_TRUE(std::isinf(stable_step(Method::ImplicitEuler, w, 0.0)));
  EXPECT_TRUE(std::isnan(stable_step(Method::RK45, w, 0.0)));
  // Damped explicit Euler: stable exactly while h <= c / w^2 (k_d / k_s for a unit mass).
  // (To 1e-6 relative: a step counts as stable while rho <= 1 + 1e-9.)
  for (double c : {0.5, 2.0, 5.0}) EXPECT_NEAR(stable_step(Method::Euler, w, c), c / (w * w), 1e-6 * c / (w * w));
  // And the table's undamped limits agree with the computed ones.
  for (const MethodInfo& m : methods()) {
    if (!std::isfinite(m.undamped_limit)) continue;
    EXPECT_NEAR(stable_step(m.id, 1.0, 0.0), m.undamped_limit, 1e-9) << m.name;
  }
}

TEST(StableStep, AmplificationFactorsAreTheKnownOnes) {
  const double w = 10.0, h = 0.05, s = (h * w) * (h * w);
  EXPECT_NEAR(amplification(Method::Euler, w, 0, h), std::sqrt(1 + s), 1e-9);
  EXPECT_NEAR(amplification(Method::Midpoint, w, 0, h), std::sqrt(1 + s * s / 4), 1e-9);
  EXPECT_NEAR(amplification(Method::ModifiedEuler, w, 0, h), std::sqrt(1 + s / 2), 1e-9);
  EXPECT_NEAR(amplification(Method::ImplicitEuler, w, 0, h), 1 / std::sqrt(1 + s), 1e-9);
  EXPECT_NEAR(amplification(Method::RK4, w, 0, 0.29), 1.19, 0.005);  // NUMERICS.md
}

// Runs `steps` steps; true if the run did not diverge.
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

TEST(Stability, DivergenceReportsStepTimeMethodAndLimit) {
  const Scene spring = test::linear_oscillator();
  Simulation sim = test::simulation(spring, Method::RK4, 0.29);
  sim.advance(1000);
  ASSERT_TRUE(sim.diverged());
  const Divergence& d = *sim.divergence();
  EXPECT_EQ(d.method, Method::RK4);
  EXPECT_DOUBLE_EQ(d.h, 0.29);
  EXPECT_NEAR(d.w_max, 10.0, 1e-6);
  EXPECT_NEAR(d.stable_h, 0.2828427, 1e-6);
  EXPECT_GT(d.step, 10);
  EXPECT_TRUE(all_finite(sim.state()));  // the last good state is kept
  const std::string message = d.message();
  for (const char* part : {"rk4", "h = 0.29", "stable up to h = 0.2828", "step"})
    EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(Stability, OnTheRestLengthSpringTheAnchorBoundsRK4sGrowth) {
  // What the teacher sees on `spring` at h = 0.29: RK4 leaves the physical motion (the energy
  // grows tenfold, the particle crosses its anchor) but the double well stops the growth.
  Simulation sim = test::simulation(test::shipped("spring"), Method::RK4, 0.29);
  double highest = 0.0, nearest = 1e9;
  for (int k = 0; k < 2000 && sim.step(); ++k) {
    highest = std::max(highest, sim.energy().total());
    nearest = std::min(nearest, std::abs(sim.state().x(1, 0)));
  }
  EXPECT_GT(highest, 10 * 12.5);
  EXPECT_LT(nearest, 0.5);  // the exact motion never comes closer than 0.5
}

TEST(Stability, ImplicitEulerHoldsWhereEveryExplicitMethodDiverges) {
  const Scene stiff = test::shipped("stiff");
  Simulation implicit = test::simulation(stiff, Method::ImplicitEuler, stiff.dt);
  EXPECT_GT(stiff.dt * implicit.stability().w_max, 10.0);
  EXPECT_EQ(implicit.advance(600), 600);  // 10 s
  for (Method m : {Method::Euler, Method::SymplecticEuler, Method::Midpoint, Method::ModifiedEuler,
                   Method::RK4, Method::Verlet})
    EXPECT_FALSE(holds(stiff, m, stiff.dt, 600)) << method_info(m).name;
}

// The highest mode of M^-1/2 K M^-1/2, assembled densely, for checking the Lanczos estimate:
// its frequency, and its damping c = u^T C u / u^T M u with u = M^-1/2 v, C = -df/dv.
struct DenseMode {
  double w_max, damping;
};
DenseMode dense_mode(const Scene& scene) {
  const Model& m = scene.model;
  const int n = m.particle_count();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n), C = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int s = 0; s < m.spring_count(); ++s) {
    const int a = m.spring_a[s], b = m.spring_b[s];
    const SpringJacobian J = spring_jacobian(scene.state.x.row(a).transpose(), scene.state.x.row(b).transpose(),
                                             Vec3::Zero(), Vec3::Zero(), m.ks(s), m.kd(s), m.rest_length[s], true);
    for (auto [M, block] : {std::pair{&K, J.dfdx}, std::pair{&C, J.dfdv}}) {
      M->block<3, 3>(3 * a, 3 * a) += block;
      M->block<3, 3>(3 * b, 3 * b) += block;
      M->block<3, 3>(3 * a, 3 * b) -= block;
      M->block<3, 3>(3 * b, 3 * a) -= block;
    }
  }
  for (int i = 0; i < n; ++i) C.block<3, 3>(3 * i, 3 * i).diagonal().array() += m.drag;
  Eigen::VectorXd scale(3 * n);
  for (int i = 0; i < n; ++i) scale.segment<3>(3 * i).setConstant(std::sqrt(m.inv_mass[i]));
  const Eigen::MatrixXd B = scale.asDiagonal() * K * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(B);
  Eigen::Index top = 0;
  const double lambda = solver.eigenvalues().maxCoeff(&top);
  const Eigen::VectorXd v = solver.eigenvectors().col(top);
  const Eigen::VectorXd u = scale.asDiagonal() * v;
  return {std::sqrt(lambda), u.dot(C * u) / v.squaredNorm()};
}
double dense_w_max(const Scene& scene) { return dense_mode(scene).w_max; }

TEST(Stability, LanczosFindsTheHighestFrequency) {
  for (const char* name : {"rope", "chain", "stiff"}) {
    const Scene scene = test::shipped(name);
    const StabilityEstimate e = estimate_stability(scene.model, scene.state);
    const double exact = dense_w_max(scene);
    EXPECT_NEAR(e.w_max, exact, 1e-6 * exact) << name;
    EXPECT_GE(e.w_bound, exact * (1 - 1e-12)) << name;  // Gershgorin bounds it from above
  }
  // A small cloth, whose highest frequencies crowd together.
  const Scene cloth = test::shipped("cloth", {"cloth.width=10", "cloth.height=10"});
  const StabilityEstimate e = estimate_stability(cloth.model, cloth.state);
  const double exact = dense_w_max(cloth);
  EXPECT_NEAR(e.w_max, exact, 1e-6 * exact);
  EXPECT_LE(e.w_max, exact * (1 + 1e-9));  // a Ritz value never overshoots
  EXPECT_TRUE(e.converged);
}

// The damping of the highest mode, which sets the limit of the methods that damping rescues
// (explicit Euler): the Lanczos mode's against the dense eigenvector's. Scenes whose highest mode
// is single (a cloth's are not: its symmetry repeats them).
TEST(Stability, LanczosModeHasTheHighestModesDamping) {
  for (const char* name : {"rope", "chain", "damped-spring"}) {
    const Scene scene = test::shipped(name);
    const StabilityEstimate e = estimate_stability(scene.model, scene.state);
    const DenseMode exact = dense_mode(scene);
    ASSERT_GT(exact.damping, 0.0) << name;
    EXPECT_NEAR(e.damping, exact.damping, 1e-6 * exact.damping) << name;
  }
}

// No stiffness at all (a spring whose ends coincide has no direction, hence no force): the
// estimate is w_max = 0 with a finite damping, not NaN.
TEST(Stability, ASceneWithoutStiffnessHasAFiniteEstimate) {
  const Scene pair = test::coincident_pair(true, 100.0, 0.5);
  const StabilityEstimate e = estimate_stability(pair.model, pair.state);
  EXPECT_EQ(e.w_max, 0.0);
  EXPECT_TRUE(std::isfinite(e.damping));
}

}  // namespace
}  // namespace springlab

namespace springlab {
namespace {

// The measured limit: the method's own step on the scene, linearised, against the oscillator
// model's limit from w_max.
TEST(MeasuredStability, OnTheSpringItIsTheTheoreticalLimitWithinTwoPercent) {
  for (const char* name : {"spring", "damped-spring"}) {
    const Scene s = test::shipped(name);
    const StabilityEstimate e = estimate_stability(s.model, s.state);
    for (const MethodInfo& m : methods()) {
      const double theory = stable_step(m.id, e.w_max, e.damping);
      const double measured = measured_stable_step(m.id, s.model, s.state, e.w_max, theory);
      if (std::isnan(theory)) {
        EXPECT_TRUE(std::isnan(measured)) << m.name;
      } else if (theory == 0.0 || std::isinf(theory)) {
        EXPECT_EQ(measured, theory) << name << " " << m.name;  // never / always stable, both ways
      } else {
        EXPECT_NEAR(measured, theory, 0.02 * theory) << name << " " << m.name;
      }
    }
  }
}

TEST(MeasuredStability, OnManyParticlesItAgreesWithTheEstimateFromWMax) {
  // Dense Jacobians (the chain, 234 coordinates) and Lanczos (a 10 x 10 cloth, 588).
  for (const auto& [name, overrides] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"chain", {}}, {"rope", {}}, {"cloth", {"cloth.width=10", "cloth.height=10"}}}) {
    const Scene s = test::shipped(name, overrides);
    const StabilityEstimate e = estimate_stability(s.model, s.state);
    for (Method m : {Method::SymplecticEuler, Method::RK4}) {
      const double theory = stable_step(m, e.w_max, e.damping);
      const double measured = measured_stable_step(m, s.model, s.state, e.w_max, theory);
      EXPECT_NEAR(measured, theory, 0.10 * theory) << name << " " << method_info(m).name;
    }
  }
}

}  // namespace
}  // namespace springlab

namespace springlab {
namespace {

// Dragging the k_s, k_d or drag slider scales the cached estimate instead of making it again: it
// must be the estimate a fresh Lanczos run gives for the changed model.
TEST(Stability, ScaledEstimateAfterAParameterChangeIsTheFreshOne) {
  const Scene scene = test::shipped("cloth", {"cloth.width=16", "cloth.height=16"});
  Simulation sim(scene.model, scene.state, SimulationSettings{});
  const double ks = sim.model().materials.front().ks, kd = sim.model().materials.front().kd;
  ASSERT_GT(sim.model().drag, 0.0);
  const auto expect_fresh = [&](const char* what) {
    const StabilityEstimate cached = sim.stability();
    const StabilityEstimate fresh = estimate_stability(sim.model(), sim.state());
    EXPECT_NEAR(cached.w_max, fresh.w_max, 1e-6 * fresh.w_max) << what;
    EXPECT_NEAR(cached.w_bound, fresh.w_bound, 1e-12 * fresh.w_bound) << what;
    EXPECT_NEAR(cached.damping, fresh.damping, 1e-6 * fresh.damping) << what;
  };
  sim.stability();
  sim.set_stiffness(3.0 * ks);
  expect_fresh("k_s");
  sim.set_damping(0.25 * kd);
  expect_fresh("k_d");
  sim.set_drag(2.0 * sim.model().drag);
  expect_fresh("drag");
  sim.set_gravity(Vec3(0.0, -3.0, 1.0));
  expect_fresh("gravity");
  // A grab pins the particle: the estimate is kept, an upper bound on the pinned scene's w_max
  // (so a safe limit), and right again once it is let go.
  const StabilityEstimate before = sim.stability();
  sim.grab(100);
  EXPECT_EQ(sim.stability().w_max, before.w_max);
  EXPECT_GE(before.w_max, estimate_stability(sim.model(), sim.state()).w_max * (1 - 1e-9));
  sim.release();
  expect_fresh("released");
  // A change that is not a scaling (a particle moved while paused) makes it again.
  sim.place(100, sim.state().x.row(100).transpose() + Vec3(0.05, 0.0, 0.0));
  expect_fresh("placed");
}

}  // namespace
}  // namespace springlab
