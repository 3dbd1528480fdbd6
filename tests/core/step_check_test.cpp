// What an explicit step measures on the side, in the same passes as its forces and update: the
// check of the new state (finite, kinetic energy) and the power damping and drag take out at the
// state it starts from. Both must equal what the separate functions of energy.hpp compute, on
// scenes of several blocks and chunks (a block's value is summed over its chunks), for any
// thread count.
#include <gtest/gtest.h>

#include "springlab/energy.hpp"
#include "springlab/forces.hpp"
#include "springlab/methods.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// A shipped scene in motion: positions and velocities jittered (every spring stretched and
// moving, the drag working).
Scene jittered(const std::string& name, const std::vector<std::string>& overrides) {
  Scene scene = test::shipped(name, overrides);
  test::jitter(scene.state, 0.02, 0.2, 11);
  return scene;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

TEST(StepCheck, ProbeAndPowerAreThoseOfTheStatesOnEveryBlockAndChunk) {
  const Scene scenes[] = {jittered("cloth", {"cloth.width=48", "cloth.height=48"}),
                          jittered("rope", {"rope.nodes=3000"}), jittered("jelly", {})};
  for (const Scene& scene : scenes) {
    for (Method method : {Method::Euler, Method::SymplecticEuler, Method::ModifiedEuler}) {
      Workspace ws;
      ws.measure_power = true;
      State out;
      step(method, scene.model, scene.state, out, 1e-5, StepSettings{}, ws);
      ASSERT_TRUE(ws.step_probe && ws.input_power) << method_info(method).name;
      if (scene.state.particle_count() > 2000) {
        EXPECT_GT(ws.spring_forces.plan.own.size(), 1u);
      }
      EXPECT_TRUE(ws.step_probe->finite);
      EXPECT_LT(relative(ws.step_probe->kinetic, kinetic_energy(scene.model, out)), 1e-12)
          << scene.name << " " << method_info(method).name;
      EXPECT_LT(relative(*ws.input_power, dissipation_power(scene.model, scene.state)), 1e-12)
          << scene.name << " " << method_info(method).name;
    }
  }
}

TEST(StepCheck, AStateThatIsNotFiniteAnywhereIsSeen) {
  Scene scene = jittered("cloth", {"cloth.width=48", "cloth.height=48"});
  // One particle in the first chunk of the first block, one in the middle of the last block.
  for (int particle : {5, scene.state.particle_count() - 300}) {
    State start = scene.state;
    start.v(particle, 1) = std::numeric_limits<double>::infinity();
    Workspace ws;
    State out;
    step(Method::SymplecticEuler, scene.model, start, out, 1e-5, StepSettings{}, ws);
    ASSERT_TRUE(ws.step_probe);
    EXPECT_FALSE(ws.step_probe->finite) << "particle " << particle;
  }
}

TEST(StepCheck, TheMeasuredPowerIsTheSameForAnyThreadCount) {
  const Scene scene = jittered("cloth", {"cloth.width=64", "cloth.height=64"});
  std::vector<double> powers;
  for (int threads : {1, 2, 3}) {
    set_thread_count(threads);
    Workspace ws;
    ws.measure_power = true;
    State out;
    step(Method::SymplecticEuler, scene.model, scene.state, out, 1e-5, StepSettings{}, ws);
    powers.push_back(*ws.input_power);
  }
  set_thread_count(0);
  EXPECT_EQ(powers[0], powers[1]);
  EXPECT_EQ(powers[0], powers[2]);
}

}  // namespace
}  // namespace springlab
