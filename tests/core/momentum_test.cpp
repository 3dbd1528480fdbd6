// Momentum on a free body (momentum.hpp): what each row of the method table keeps, measured, and
// held to what the row says (MethodInfo::momentum, angular_momentum), both ways: a row that says
// "kept" keeps it to rounding, one that says "not kept" visibly breaks it.
#include <gtest/gtest.h>

#include <filesystem>

#include "springlab/butcher.hpp"
#include "springlab/methods.hpp"
#include "springlab/momentum.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// An 8 x 8 cloth with nothing pinned, no gravity, drag or ground: jittered, every particle moving
// at random, so that the springs stretch, shear and bend while the body drifts and spins. Damped
// along its springs (a force between two particles, which keeps P and L), so that every explicit
// row has a limit the automatic sub-steps keep within, and each breaks L visibly at half of it
// (measured: rk45 3.6e-7, every other row that does not keep it above 1e-6; those that keep it
// 1e-12 at most, P 1e-11 at most).
Scene free_cloth() {
  Scene s = test::shipped("cloth", {"cloth.width=8", "cloth.height=8", "cloth.pinned=[]", "gravity=[0,0,0]", "drag=0", "cloth.damping=0.5"});
  test::jitter(s.state, 0.02, 1.0, 7);
  return s;
}

MomentumChange change_over(const Scene& scene, Method method, int steps, int iterations = 0) {
  // One analysis of the scene for every row (its equilibrium is the costly part).
  static std::shared_ptr<const StabilityAnalysis> analysis;
  SimulationSettings settings;
  settings.method = method;
  settings.dt = 1.0 / 60.0;
  settings.step.tolerance = scene.tolerance;
  Simulation sim(scene.model, scene.state, settings);
  if (analysis) sim.set_stability(analysis);
  sim.stability();
  analysis = sim.stability_if_any();
  sim.set_auto_substeps(scene.safety);  // (sub-steps: half the limit)
  StepSettings step = sim.settings().step;
  step.iterations = iterations;
  sim.set_step_settings(step);
  const Momentum before = momentum(sim.model(), sim.state());
  for (int k = 0; k < steps && sim.step();) ++k;
  EXPECT_FALSE(sim.diverged()) << method_info(method).name << ": " << sim.explain_divergence()->message();
  return momentum_change(before, momentum(sim.model(), sim.state()));
}

// Every row, the shipped tableaux' included.
std::vector<Method> every_row() {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/tableaux"))
    if (entry.path().extension() == ".json")
      add_tableau_method(load_tableau_file(entry.path().string()), "tableau-" + entry.path().stem().string());  // (as the other tests name them: one row each)
  return test::methods_where([](const MethodInfo&) { return true; });
}

void expect(Kept said, double measured, const std::string& what) {
  switch (said) {
    case Kept::Exactly: EXPECT_LE(measured, kMomentumKept) << what; break;
    case Kept::ToSolverTolerance: EXPECT_LE(measured, 1e-3) << what; break;  // CG to 1e-5, Newton to 1e-10
    case Kept::No: EXPECT_GT(measured, 1e-8) << what; break;  // (rounding: 1e-15 a step)
  }
}

TEST(Momentum, EachRowKeepsWhatItSays) {
  const Scene scene = free_cloth();
  ASSERT_TRUE(free_body(scene.model));
  for (Method method : every_row()) {
    const MethodInfo& m = method_info(method);
    const MomentumChange c = change_over(scene, method, 30);
    expect(m.momentum, c.linear, std::string(m.name) + ": P " + kept_text(m.momentum));
    expect(m.angular_momentum, c.angular, std::string(m.name) + ": L " + kept_text(m.angular_momentum));
  }
}

// VBD's break is its unfinished iteration's, not the model's: converged, its step is the
// backward-Euler step, which keeps P (the springs' forces sum to zero at any state).
TEST(Momentum, VertexBlockDescentKeepsItOnlyConverged) {
  const Scene scene = free_cloth();
  const double ten = change_over(scene, Method::VBD, 1, 10).linear;
  const double converged = change_over(scene, Method::VBD, 1, 2000).linear;
  EXPECT_GT(ten, 1e-2);  // measured 5.5e-2
  EXPECT_LT(converged, 1e-9);
}

// Cooper's condition read from the tableaux: implicit midpoint is symplectic, the trapezoidal
// rule, RK4 and implicit Euler are not.
TEST(Momentum, SymplecticTableauxByCoopersCondition) {
  const auto shipped = [](const std::string& name) {
    return analyse_tableau(load_tableau_file(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/tableaux/" + name + ".json"));
  };
  EXPECT_TRUE(shipped("implicit-midpoint").symplectic);
  EXPECT_FALSE(shipped("trapezoidal").symplectic);
  EXPECT_FALSE(shipped("rk4").symplectic);
  EXPECT_FALSE(shipped("implicit-euler").symplectic);
  EXPECT_FALSE(shipped("sdirk2").symplectic);
}

// Where an outside force acts, momentum is no constant, and free_body() says so.
TEST(Momentum, OnlyAFreeBodyIsFree) {
  EXPECT_FALSE(free_body(test::shipped("cloth").model));                                    // pinned, gravity
  EXPECT_FALSE(free_body(test::shipped("cloth", {"cloth.pinned=[]", "drag=0"}).model));     // gravity
  EXPECT_FALSE(free_body(test::shipped("jelly", {"gravity=[0,0,0]", "drag=0"}).model));     // the ground
  EXPECT_TRUE(free_body(test::shipped("jelly", {"gravity=[0,0,0]", "drag=0", "colliders=[]"}).model));
}

}  // namespace
}  // namespace springlab
