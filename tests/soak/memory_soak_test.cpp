// Soak: a long headless run keeps its memory flat. A million steps of the cloth (8 x 8, so that
// they take seconds: per-step allocations do not depend on the size), and a shorter run of every
// method. Memory is measured twice, after a warm-up and at the end, as the heap in use (exact:
// glibc's mallinfo2, every arena) and as the resident set (/proc/self/statm, what a user sees).
// A leak of one small allocation every thousand steps fails the million-step test.
#include <gtest/gtest.h>
#include <malloc.h>
#include <unistd.h>

#include <fstream>

#include "support.hpp"

namespace springlab {
namespace {

struct Memory {
  long heap = 0;      // bytes allocated and not freed
  long resident = 0;  // bytes
};

Memory memory_now() {
  Memory m;
  m.heap = static_cast<long>(mallinfo2().uordblks);
  std::ifstream statm("/proc/self/statm");
  long size = 0, pages = 0;
  statm >> size >> pages;
  m.resident = pages * sysconf(_SC_PAGESIZE);
  return m;
}

Scene small_cloth() {
  return test::shipped("cloth", {"cloth.width=8", "cloth.height=8"});
}

TEST(Soak, AMillionStepsOfTheClothKeepMemoryFlat) {
  const Scene scene = small_cloth();
  Simulation sim = test::simulation(scene, scene.methods.front(), scene.dt, scene.substeps);
  ASSERT_EQ(sim.advance(100'000), 100'000);
  const Memory warm = memory_now();
  ASSERT_EQ(sim.advance(900'000), 900'000) << sim.divergence()->message();
  const Memory end = memory_now();
  EXPECT_LE(end.heap - warm.heap, 16 << 10) << "heap grew from " << warm.heap << " to " << end.heap;
  EXPECT_LE(end.resident - warm.resident, 512 << 10)
      << "resident set grew from " << warm.resident << " to " << end.resident;
}

TEST(Soak, EveryMethodKeepsItsHeapFlat) {
  const Scene scene = small_cloth();
  for (const MethodInfo& m : methods()) {
    // A step short enough for explicit Euler, unstable at any step, to grow only twofold.
    Simulation sim = test::simulation(scene, m.id, scene.dt / 32);
    ASSERT_EQ(sim.advance(1'000), 1'000) << m.name;
    const Memory warm = memory_now();
    ASSERT_EQ(sim.advance(10'000), 10'000) << m.name << ": " << sim.divergence()->message();
    const Memory end = memory_now();
    EXPECT_LE(end.heap - warm.heap, 4 << 10)
        << m.name << ": heap grew from " << warm.heap << " to " << end.heap;
  }
}

}  // namespace
}  // namespace springlab
