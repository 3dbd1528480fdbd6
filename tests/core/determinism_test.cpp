// Determinism: the same scene, method and inputs give a bit-identical state, run after run and
// whatever the number of threads.
#include <gtest/gtest.h>

#include "springlab/forces.hpp"
#include "support.hpp"

namespace springlab {
namespace {

std::uint64_t run_hash(const Scene& scene, Method method, int threads, int steps) {
  set_thread_count(threads);
  Simulation sim = test::simulation(scene, method, scene.dt);
  sim.advance(steps);
  set_thread_count(0);
  return state_hash(sim.state());
}

TEST(Determinism, SameRunSameBits) {
  const Scene scene = test::shipped("cloth-sphere");
  EXPECT_EQ(run_hash(scene, Method::SymplecticEuler, 0, 300), run_hash(scene, Method::SymplecticEuler, 0, 300));
}

TEST(Determinism, ThreadCountDoesNotChangeABit) {
  // Big enough for the force loops to run in parallel.
  const Scene scene = test::shipped("cloth", {"cloth.width=48", "cloth.height=48"});
  for (Method method : {Method::SymplecticEuler, Method::RK4, Method::ImplicitEuler, Method::Verlet, Method::RK45}) {
    const auto one = run_hash(scene, method, 1, 40);
    const auto two = run_hash(scene, method, 2, 40);
    const auto three = run_hash(scene, method, 3, 40);
    EXPECT_EQ(one, two) << method_info(method).name;
    EXPECT_EQ(one, three) << method_info(method).name;
  }
  // More threads than blocks (and than cores): threads with one block, or none, waiting on others.
  EXPECT_EQ(run_hash(scene, Method::SymplecticEuler, 1, 40), run_hash(scene, Method::SymplecticEuler, 12, 40));
}

TEST(Determinism, HashSeesTheSmallestChange) {
  const Scene scene = test::shipped("spring");
  State s = scene.state;
  const auto before = state_hash(s);
  s.x(1, 0) = std::nextafter(s.x(1, 0), 2.0);
  EXPECT_NE(state_hash(s), before);
}

}  // namespace
}  // namespace springlab
