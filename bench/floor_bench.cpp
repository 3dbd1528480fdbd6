// The floor: how fast this machine can take a 1000-node rope's symplectic Euler step at all.
// Not springlab's code path but the least work the step needs, written as one loop: the same
// force law (spring_scale(), spring_kernel.hpp), gravity and drag, the update and the step's
// check (probe_term(), energy.hpp), four particles at a time, in AVX2 registers from load to
// store, the springs of the next four computed while the last four are updated (software
// pipelining: the force's square root and division are a long chain). With 2 threads, the
// second one runs the other half of the rope and the two hand over through spin flags, the
// cheapest hand-over there is (no OpenMP region, no sleeping). The ns per spring per step it
// reports are what the rope target (2 ns) is to be held against (docs/performance.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#include "springlab/energy.hpp"
#include "springlab/simd.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {
namespace {

using simd::f64x4;

struct Rope {
  static constexpr int kNodes = 1000;  // a multiple of 4
  std::vector<double> x[3], v[3], x1[3], v1[3], mass, inv_mass;
  double ks = 1e6, kd = 10.0, rest = 1e-3, drag = 0.01, h = 1e-5, g[3] = {0.0, -9.81, 0.0};

  Rope() {
    for (int c = 0; c < 3; ++c)
      for (auto* a : {&x[c], &v[c], &x1[c], &v1[c]}) a->assign(kNodes + simd::kLanes, 0.0);
    for (int i = 0; i < kNodes; ++i) x[0][i] = i * rest;
    mass.assign(kNodes + simd::kLanes, 1e-3);
    inv_mass.assign(kNodes + simd::kLanes, 1e3);
    inv_mass[0] = 0.0;  // pinned
  }
  void swap() {
    for (int c = 0; c < 3; ++c) {
      std::swap(x[c], x1[c]);
      std::swap(v[c], v1[c]);
    }
  }

  // Particles [lo, hi), a multiple of 4 apart; returns their check (the probe's sum).
  double step(int lo, int hi) {
    using simd::at;
    const double* X[3] = {x[0].data(), x[1].data(), x[2].data()};
    const double* V[3] = {v[0].data(), v[1].data(), v[2].data()};
    double* X1[3] = {x1[0].data(), x1[1].data(), x1[2].data()};
    double* V1[3] = {v1[0].data(), v1[1].data(), v1[2].data()};
    const double *m = mass.data(), *w = inv_mass.data();
    // The force of springs i .. i + 3 on their a-ends (i + 1 .. i + 4 their b-ends).
    const auto springs = [&](int i, f64x4 f[3]) {
      f64x4 d[3], rate{};
      for (int c = 0; c < 3; ++c) d[c] = at<f64x4>(X[c] + i + 1) - at<f64x4>(X[c] + i);
      for (int c = 0; c < 3; ++c) rate += (at<f64x4>(V[c] + i + 1) - at<f64x4>(V[c] + i)) * d[c];
      f64x4 s = spring_scale<true>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], rate, ks, kd, rest);
      if (i + simd::kLanes >= kNodes)
        s = simd::first_lanes(s, kNodes - 1 - i);  // the last has none
      for (int c = 0; c < 3; ++c) f[c] = s * d[c];
    };
    f64x4 before[3] = {}, now[3], next[3] = {}, sum{};
    if (lo > 0) springs(lo - simd::kLanes, before);
    springs(lo, now);
    for (int i = lo; i < hi; i += simd::kLanes) {
      if (i + simd::kLanes < hi) springs(i + simd::kLanes, next);
      const f64x4 mi = at<f64x4>(m + i), wi = at<f64x4>(w + i);
      f64x4 xn[3], vn[3];
      for (int c = 0; c < 3; ++c) {
        const f64x4 vc = at<f64x4>(V[c] + i);
        const f64x4 f = (mi * g[c] - drag * vc) + (now[c] - simd::shifted_in<1>(before[c], now[c]));
        vn[c] = vc + h * (f * wi);
        xn[c] = at<f64x4>(X[c] + i) + h * vn[c];
        simd::store(X1[c] + i, xn[c]);
        simd::store(V1[c] + i, vn[c]);
        before[c] = now[c];
        now[c] = next[c];
      }
      sum += probe_term(wi, mi, vn, xn);
    }
    return simd::sum(sum);
  }
};

void BM_RopeFloor(benchmark::State& state) {
  Rope rope;
  const int threads = static_cast<int>(state.range(0));
  const int half = Rope::kNodes / 2;
  // The two flags on lines of their own: each is written by one thread and read by the other.
  alignas(64) std::atomic<std::int64_t> go{0};
  alignas(64) std::atomic<std::int64_t> done{0};
  double helper_check = 0.0;  // kept, so that the helper's half does its check too
  std::thread helper;
  if (threads == 2)
    helper = std::thread([&] {
      for (std::int64_t n = 1;; ++n) {
        std::int64_t wanted;
        while ((wanted = go.load(std::memory_order_acquire)) >= 0 && wanted < n)
          __builtin_ia32_pause();
        if (wanted < 0) return;
        helper_check += rope.step(half, Rope::kNodes);
        done.store(n, std::memory_order_release);
      }
    });
  std::int64_t n = 0;
  double check = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    if (threads == 2) {
      go.store(++n, std::memory_order_release);
      check += rope.step(0, half);
      while (done.load(std::memory_order_acquire) < n) __builtin_ia32_pause();
    } else {
      check += rope.step(0, Rope::kNodes);
    }
    rope.swap();
  }
  if (threads == 2) {
    go.store(-1, std::memory_order_release);
    helper.join();
  }
  const double ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  benchmark::DoNotOptimize(check);
  benchmark::DoNotOptimize(helper_check);
  state.counters["ns_per_spring"] =
      ns / (static_cast<double>(state.iterations()) * (Rope::kNodes - 1));
}
BENCHMARK(BM_RopeFloor)->Arg(1)->Arg(2)->UseRealTime();

// The floor of a hand-over between two threads: a cache line sent to the other thread and back
// (each spins until the line holds its turn). The team's jobs (core/src/dynamics/threads.*) wait
// for such a line a few times each; on this project's virtual machines the two cores are now 83 ns
// apart and now 380 (placed apart by the host, minutes at a time), and a CG iteration's three jobs
// cost accordingly (docs/performance.md). Counter: ns a round trip.
constexpr std::int64_t kCoreToCoreTrips = 20000;
void BM_CoreToCore(benchmark::State& state) {
  alignas(64) static std::atomic<std::int64_t> turn{0};
  const std::int64_t first = turn.load();
  // Trip k: this thread writes its turn (odd), the other answers (even).
  const auto wait_for = [&](std::int64_t value) {
    while (turn.load(std::memory_order_acquire) != value) {
    }
  };
  std::thread other([&] {
    for (std::int64_t k = 0; k < kCoreToCoreTrips; ++k) {
      wait_for(first + 2 * k + 1);
      turn.store(first + 2 * k + 2, std::memory_order_release);
    }
  });
  std::int64_t trips = 0;
  const auto trip = [&] {
    turn.store(first + 2 * trips + 1, std::memory_order_release);
    wait_for(first + 2 * trips + 2);
    ++trips;
  };
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) trip();  // (exactly kCoreToCoreTrips: Iterations below)
  const double ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  while (trips < kCoreToCoreTrips)
    trip();  // (never, unless run with other iterations: the other thread ends)
  other.join();
  state.counters["ns_round_trip"] =
      ns / static_cast<double>(std::max<std::int64_t>(state.iterations(), 1));
}
BENCHMARK(BM_CoreToCore)->Iterations(kCoreToCoreTrips)->UseRealTime();

}  // namespace
}  // namespace springlab
