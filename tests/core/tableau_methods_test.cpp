// Tableaux run as methods (add_tableau_method): each shipped tableau's order measured on the
// spring against its exact solution, its stated limit held just inside and broken just outside
// by runs, and implicit midpoint's energy kept where implicit Euler's is lost.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "springlab/butcher.hpp"
#include "springlab/energy.hpp"
#include "springlab/error.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

namespace fs = std::filesystem;

// Each shipped tableau as a row of its own, named "tableau-<file>" (the built-in names are taken).
Method row(const std::string& file) {
  const ButcherTableau t = load_tableau_file(
      (fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "tableaux" / (file + ".json")).string());
  return add_tableau_method(t, "tableau-" + file);
}

std::vector<std::string> shipped_tableaux() {
  std::vector<std::string> names;
  for (const auto& e :
       fs::directory_iterator(fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "tableaux"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The order its conditions give (to rounding) is the slope measured by halving h on the
// spring, from (h w)^p = 1e-2 (as for the built-in rows: accuracy_test.cpp), within 0.2; and,
// for a tableau with implicit stages, still from a step 16 times finer, where the stages'
// solver error would show first (tableau_steps.cpp: at implicit Euler's 1e-5 SDIRK3's slope
// there was 0.1, SDIRK2's and implicit midpoint's turned negative). (An explicit tableau's
// errors there approach rounding.)
TEST(TableauMethods, OrderOnTheSpringIsTheConditionsOrder) {
  const Scene scene = test::shipped("spring");
  for (const std::string& name : shipped_tableaux()) {
    const Method m = row(name);
    if (method_info(m).adaptive()) continue;  // an embedded pair chooses its steps (below)
    const int order = method_info(m).order;
    const double h0 = std::pow(1e-2, 1.0 / order) / 10.0;
    const bool implicit = !tableau_source(m)->is_explicit();
    for (const double h : implicit ? std::vector<double>{h0, h0 / 16.0} : std::vector<double>{h0}) {
      const double coarse = test::error_against_exact(scene, m, h, 1.0);
      const double fine = test::error_against_exact(scene, m, h / 2, 1.0);
      const double finer = test::error_against_exact(scene, m, h / 4, 1.0);
      EXPECT_NEAR(std::log2(coarse / fine), order, 0.2)
          << name << " h " << h << " errors " << coarse << " " << fine;
      EXPECT_NEAR(std::log2(fine / finer), order, 0.2)
          << name << " h " << h << " errors " << fine << " " << finer;
    }
  }
}

// The stated limit on a damped linear spring (damping ratio 0.1; the analysis, from the tableau's
// R(z)) is where runs turn: 2000 steps at 0.95 of it end with less energy than they started with
// (a stable step may first raise it: |R| near 1 is not a contraction in the energy norm), at 1.25
// of it the energy grows past tenfold. A tableau stable at any step loses energy even at h w = 100
// (on `damped-spring`: the same k_s, k_d and start).
// (Linear, as the built-in rows' limits tests are: on `damped-spring`, rest length 1, a step near
// the limit can pump the particle through its anchor, where the double well is another problem.)
TEST(TableauMethods, StatedLimitHoldsInsideAndBreaksOutside) {
  const Scene scene = test::linear_oscillator(100.0, 2.0), damped = test::shipped("damped-spring");
  std::vector<Method> rows;
  for (const std::string& name : shipped_tableaux()) rows.push_back(row(name));
  const StabilityAnalysis a(scene.model, scene.state);
  const double start = energy(scene.model, scene.state).total();
  const auto end_energy = [&](Method m, double h, bool report = false) {
    Simulation sim = test::simulation(scene, m, h);
    for (int k = 0; k < 2000 && !sim.diverged(); ++k) sim.advance(1);
    if (report && sim.diverged()) ADD_FAILURE() << sim.divergence()->message();
    return sim.diverged() ? std::numeric_limits<double>::infinity() : sim.energy().total();
  };
  for (Method m : rows) {
    SCOPED_TRACE(method_info(m).name);
    if (method_info(m).adaptive()) continue;
    const StabilityLimit& limit = a.limit(m);
    if (std::isinf(limit.h)) {
      // On `damped-spring` (rest length 1): the zero-length spring's damping k_d (dv . u) u is not
      // differentiable at its anchor, where h w = 100 takes the particle within a step or two,
      // and there the stages' Newton iteration cannot converge (it says so). Here a stage's start
      // can lie past the anchor, in the other well of k_s (|x| - 1)^2 / 2: the problem the stages
      // solve is nonlinear. The trapezoidal rule is not B-stable (Butcher's algebraic stability:
      // its M = B A + A^T B - b b^T = diag(-1/4, 1/4) is indefinite), and on this dissipative
      // nonlinear problem it raises the energy from a low by 0.29 J in 80 s, which the audit
      // reports; the algebraically stable ones (implicit Euler, implicit midpoint, the SDIRKs) lose
      // it.
      Simulation sim = test::simulation(damped, m, 100.0 / a.w_max());
      for (int k = 0; k < 2000 && !sim.diverged(); ++k) sim.advance(1);
      if (std::string(method_info(m).name) == "tableau-trapezoidal") {
        ASSERT_TRUE(sim.diverged());
        EXPECT_NE(sim.divergence()->message().find("rose by 0.28"), std::string::npos)
            << sim.divergence()->message();
        continue;
      }
      ASSERT_FALSE(sim.diverged()) << sim.divergence()->message();
      EXPECT_LT(sim.energy().total(), start);
      continue;
    }
    ASSERT_GT(limit.h, 0.0);
    EXPECT_LT(end_energy(m, 0.95 * limit.h, true), start);
    EXPECT_GT(end_energy(m, 1.25 * limit.h), 10.0 * start);
  }
}

// Implicit midpoint is A-stable and |R| = 1 on the imaginary axis: on the undamped spring at
// h w = 1 it keeps the energy to round-off over 1000 periods; implicit Euler loses almost all of
// it (|R(i)| = 1/sqrt(2): the energy halves every step), and so does Alexander's L-stable SDIRK2.
TEST(TableauMethods, ImplicitMidpointKeepsTheUndampedSpringsEnergy) {
  const Scene scene = test::linear_oscillator(100.0, 0.0);  // w = 10
  const double h = 0.1, periods = 1000.0;
  const auto steps = static_cast<int>(std::llround(periods * 2.0 * M_PI / 10.0 / h));
  const auto final_energy = [&](Method m) {
    SimulationSettings s;
    s.method = m;
    s.dt = h;
    s.substeps = 1;
    s.auto_substeps = false;
    Simulation sim(scene.model, scene.state, s);
    for (int k = 0; k < steps; ++k) EXPECT_TRUE(sim.step());
    return sim.energy().total();
  };
  const double e0 = energy(scene.model, scene.state).total();
  EXPECT_NEAR(final_energy(row("implicit-midpoint")), e0, 1e-10 * e0);
  EXPECT_NEAR(final_energy(row("trapezoidal")), e0, 1e-10 * e0);
  EXPECT_LT(final_energy(Method::ImplicitEuler), 1e-6 * e0);
  EXPECT_LT(final_energy(row("sdirk2")), 1e-6 * e0);
}

// The rope of a few nodes swinging under gravity (nonlinear: its springs turn as it swings), the
// DIRK stages solved to convergence (Newton's corrections, implicit_euler.hpp). With each stage
// linearised once they would be a method of Rosenbrock type, not the tableau's.
Scene swinging_rope(int nodes, double stiffness, double damping) {
  return test::shipped(
      "rope", {"rope.nodes=" + std::to_string(nodes), "rope.stiffness=" + std::to_string(stiffness),
               "rope.damping=" + std::to_string(damping), "drag=0"});
}

// Positions at t = T k / 8, k = 1..8, stepping h = T / steps (steps a multiple of 8).
std::vector<Points> samples(const Scene& scene, Method method, int steps, double duration) {
  SimulationSettings s;
  s.method = method;
  s.dt = duration / steps;
  s.substeps = 1;
  s.auto_substeps = false;
  Simulation sim(scene.model, scene.state, s);
  std::vector<Points> out;
  for (int k = 1; k <= steps; ++k) {
    EXPECT_TRUE(sim.step()) << method_info(method).name;
    if (k % (steps / 8) == 0) out.push_back(sim.state().x);
  }
  return out;
}

double largest_rms(const Model& model, const std::vector<Points>& a, const std::vector<Points>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, test::rms_over_free(model, a[k], b[k]));
  return worst;
}

// On the swinging rope (four nodes, w_max about 40 rad/s), against RK4 at 1/20000 s: the slope of
// log error against log h over h = 1/40 .. 1/320 s (h w_max 1 to 1/8) is the tableau's order
// within 0.2: SDIRK3 3, SDIRK2 2, implicit midpoint 2, the trapezoidal rule 2, Qin and Zhang 2.
TEST(TableauMethods, DiagonallyImplicitTableauxHaveTheirOrdersOnASwingingRope) {
  const Scene scene = swinging_rope(4, 200.0, 0.2);
  const double duration = 1.0;
  const std::vector<Points> reference = samples(scene, Method::RK4, 20000, duration);
  for (const auto& [name, order] :
       {std::pair{"sdirk3", 3}, std::pair{"sdirk2", 2}, std::pair{"implicit-midpoint", 2},
        std::pair{"trapezoidal", 2}, std::pair{"qin-zhang", 2}}) {
    SCOPED_TRACE(name);
    const Method m = row(name);
    std::vector<double> log_h, log_e;
    for (int steps : {40, 80, 160, 320}) {
      const double e = largest_rms(scene.model, samples(scene, m, steps, duration), reference);
      log_h.push_back(std::log(duration / steps));
      log_e.push_back(std::log(e));
    }
    // Least squares slope.
    const double n = static_cast<double>(log_h.size());
    double sh = 0, se = 0, shh = 0, she = 0;
    for (std::size_t k = 0; k < log_h.size(); ++k)
      sh += log_h[k], se += log_e[k], shh += log_h[k] * log_h[k], she += log_h[k] * log_e[k];
    const double slope = (n * she - sh * se) / (n * shh - sh * sh);
    EXPECT_NEAR(slope, order, 0.2)
        << "errors " << std::exp(log_e[0]) << " .. " << std::exp(log_e.back());
  }
}

// Implicit midpoint is symplectic: on a swinging double pendulum (a rope of three nodes, its
// links 2 m, undamped, w_max about 57 rad/s: h w_max 0.57) its energy error stays bounded over
// 1000 periods, no drift: the largest error in the last tenth of the run is within twice the
// first tenth's.
TEST(TableauMethods, ImplicitMidpointsEnergyErrorStaysBoundedOnASwingingRope) {
  const Scene scene = swinging_rope(3, 1000.0, 0.0);
  const double period = 2.0 * M_PI * std::sqrt(2.0 / 9.81), h = 0.01;
  const long steps = std::lround(1000.0 * period / h);
  SimulationSettings s;
  s.method = row("implicit-midpoint");
  s.dt = h;
  s.substeps = 1;
  s.auto_substeps = false;
  Simulation sim(scene.model, scene.state, s);
  const double e0 = sim.energy().total();
  double first = 0.0, last = 0.0;
  for (long k = 1; k <= steps; ++k) {
    ASSERT_TRUE(sim.step()) << k;
    const double error = std::abs(sim.energy().total() - e0);
    if (k <= steps / 10) first = std::max(first, error);
    if (k > steps - steps / 10) last = std::max(last, error);
  }
  EXPECT_GT(first, 0.0);
  EXPECT_LT(last, 2.0 * first) << "first tenth " << first << " J, last tenth " << last << " J";
}

// Where a stage's Newton iteration cannot converge, even with the step halved four times, the
// step fails and says which stage and why, as the method's equations not solved, never as a
// divergence: the zero-length damped spring collapsed onto its anchor at h w = 100, where its
// force's direction is not defined (G has no root there), the state before kept.
TEST(TableauMethods, AStageThatIsNotSolvedIsSaidToBeUnsolvedNotDiverged) {
  const Scene scene = test::linear_oscillator(100.0, 2.0);
  Simulation sim = test::simulation(scene, row("sdirk2"), 10.0);
  for (int k = 0; k < 200 && !sim.diverged(); ++k) sim.advance(1);
  ASSERT_TRUE(sim.diverged());
  ASSERT_TRUE(sim.divergence()->unsolved);
  const std::string message = sim.divergence()->message();
  EXPECT_NE(
      message.find("stage 1 of the tableau: the equations were not solved: Newton's iteration"),
      std::string::npos)
      << message;
  EXPECT_NE(
      message.find(
          "the method's own equations were not solved at this step (the state did not blow up)"),
      std::string::npos)
      << message;
  EXPECT_EQ(message.find("diverged"), std::string::npos) << message;
  EXPECT_GT(sim.counters().halved_steps, 0);
  EXPECT_TRUE(std::isfinite(sim.state().x.norm()));
}

// Every implicit tableau shipped runs every shipped scene with springs at the scene's own step
// and at one step a frame, as implicit Euler does, its stages solved (Newton's corrections
// counted; a step whose stages are not solved whole is halved, and that is counted too). The
// runs here are a quarter of a second each, the cloth 8 x 8 (every tableau on every scene as
// shipped, both steps, a second each, ran in the commit that made the stages Newton's: 96 of 96).
TEST(TableauMethods, EveryImplicitTableauRunsEverySceneWhereImplicitEulerDoes) {
  std::vector<std::string> implicit;
  for (const std::string& name : shipped_tableaux())
    if (!load_tableau_file(
             (fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "tableaux" / (name + ".json")).string())
             .is_explicit())
      implicit.push_back(name);
  ASSERT_GE(implicit.size(), 5u);
  // (The cloth at 8 x 8: its springs and pins as shipped, a factorisation cheap enough for a test.)
  for (const char* scene_name :
       {"spring", "damped-spring", "rope", "chain", "stiff", "jelly", "cloth"}) {
    const Scene scene = std::string(scene_name) == "cloth"
                            ? test::shipped("cloth", {"cloth.width=8", "cloth.height=8"})
                            : test::shipped(scene_name);
    for (double dt : {scene.dt, 1.0 / 60.0}) {
      Simulation reference = test::simulation(scene, Method::ImplicitEuler, dt);
      const int steps = static_cast<int>(std::ceil(0.25 / dt));
      ASSERT_EQ(reference.advance(steps), steps) << scene_name;
      for (const std::string& name : implicit) {
        SCOPED_TRACE(std::string(scene_name) + ", " + name + ", dt = " + std::to_string(dt));
        Simulation sim = test::simulation(scene, row(name), dt);
        EXPECT_EQ(sim.advance(steps), steps)
            << (sim.divergence() ? sim.divergence()->message() : "");
        EXPECT_GT(sim.counters().linear_solves, 0);  // its stages' first guesses
        // Past the linear spring, the stages are nonlinear: solved by Newton's corrections.
        if (scene.model.spring_count() > 1) {
          EXPECT_GT(sim.counters().newton_corrections, 0);
        }
      }
    }
  }
}

// A tableau with an embedded b_hat chooses its own steps: tightening the tolerance 10^4-fold cuts
// the error at least 100-fold (global error goes as a power of the tolerance below one), and
// Dormand-Prince as data is springlab's rk45 step for step: the same internal steps, the same
// state.
TEST(TableauMethods, EmbeddedPairsAdaptTheirSteps) {
  const Scene scene = test::shipped("spring");
  for (const char* name : {"bogacki-shampine", "fehlberg45", "cash-karp", "dormand-prince"}) {
    SCOPED_TRACE(name);
    const Method m = row(name);
    ASSERT_TRUE(method_info(m).adaptive());
    const double loose = test::error_against_exact(scene, m, 0.05, 2.0, 1e-4);
    const double tight = test::error_against_exact(scene, m, 0.05, 2.0, 1e-8);
    EXPECT_LT(tight, 1e-2 * loose) << loose << " " << tight;
    EXPECT_LT(tight, 1e-5);
  }
  const Method dp = row("dormand-prince");
  SimulationSettings s;
  s.dt = 0.05;
  s.step.tolerance = 1e-6;
  s.method = dp;
  Simulation data(scene.model, scene.state, s);
  s.method = Method::RK45;
  Simulation built_in(scene.model, scene.state, s);
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(data.step());
    ASSERT_TRUE(built_in.step());
  }
  EXPECT_EQ(data.counters().accepted, built_in.counters().accepted);
  EXPECT_EQ(data.counters().rejected, built_in.counters().rejected);
  EXPECT_LT((data.state().x - built_in.state().x).norm(), 1e-12);
}

// A tableau's row is added once: the same name and entries give the same row; another tableau
// under that name, or a built-in's name, is refused.
TEST(TableauMethods, NamesAreOneRowEach) {
  const Method heun = row("heun");
  EXPECT_EQ(row("heun"), heun);
  EXPECT_EQ(find_method("tableau-heun"), heun);
  EXPECT_EQ(method_info(heun).order, 2);
  const ButcherTableau ralston =
      parse_tableau(R"({"A": [[0], ["2/3"]], "b": ["1/4", "3/4"]})", "test");
  EXPECT_THROW(add_tableau_method(ralston, "tableau-heun"), InputError);
  EXPECT_THROW(add_tableau_method(ralston, "rk4"), InputError);
}

}  // namespace
}  // namespace springlab
