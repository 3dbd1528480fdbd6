// The browser computes the same physics: the state after a fixed run of shipped scenes, hashed to
// the bit (state_hash), is pinned here, and this test runs both natively (core_tests, one
// thread) and compiled to WebAssembly in Chromium (tests/web). Both have IEEE doubles, no FMA
// contraction (-ffp-contract=off) and the same summation order, so the bits agree where the
// arithmetic is IEEE's (not sin, cos, exp: the C libraries round those differently); a change to
// the physics changes the pins on purpose (the native run prints the new value).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "springlab/forces.hpp"
#include "support.hpp"

namespace springlab {
namespace {

struct Pinned {
  const char* scene;
  std::vector<std::string> overrides;
  Method method;
  int steps;
  std::uint64_t hash;
};

TEST(StateHash, SameBitsNativeAndInTheBrowser) {
  const Pinned cases[] = {
      {"spring", {}, Method::Euler, 1000, 0x94ae06ff9ec92590ull},
      {"rope", {}, Method::SymplecticEuler, 2000, 0xa78519cf3fe4ff0cull},
      {"rope", {}, Method::RK4, 500, 0x730573bf42f010fcull},
      {"cloth", {}, Method::Verlet, 300, 0xe2226b9677c3a37bull},
      {"cloth", {}, Method::ImplicitEuler, 30, 0x1daadc547b4fd6f7ull},
      // The iterative rows: local-global's factor (AMD's order, its solves' sums as a tree),
      // XPBD's and VBD's colourings.
      {"cloth", {}, Method::LocalGlobal, 30, 0x0c96a4e2fb0571c9ull},
      {"cloth", {}, Method::XPBD, 100, 0x2e4717adb1d9567dull},
      {"cloth", {}, Method::VBD, 30, 0x40baf5bcfcf98f40ull},
      // (Not rotated as shipped: a rotation's sin and cos come from the C library, whose last
      // bits differ between glibc and the browser's musl; the physics is then the same.)
      {"jelly", {"jelly.rotation=[0,0,0]"}, Method::Midpoint, 300, 0x76abb7258da01decull},
  };
  set_thread_count(1);
  for (const Pinned& c : cases) {
    const Scene scene = test::shipped(c.scene, c.overrides);
    SimulationSettings s;
    s.method = c.method;
    s.dt = scene.dt;
    s.audit_fraction = 0.0;  // the physics' bits: explicit Euler's growth on `spring` is the point
    Simulation sim(scene.model, scene.state, s);
    ASSERT_EQ(sim.advance(c.steps), c.steps) << c.scene;
    const std::uint64_t hash = state_hash(sim.state());
    EXPECT_EQ(hash, c.hash) << c.scene << ", " << method_info(c.method).name << ", " << c.steps
                            << " steps: 0x" << std::hex << hash;
  }
  set_thread_count(0);
}

}  // namespace
}  // namespace springlab
