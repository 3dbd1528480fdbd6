// The methods games and films use (XPBD, local-global, vertex block descent) on cloth, each in
// one run beside implicit Euler with conjugate gradients on the same cloth, and local-global's
// floor: one local pass plus one pair of triangular solves, what an iteration cannot go below.
// Run: build/bench/springlab_bench --benchmark_filter=Iterative (figures in the README).
#include <benchmark/benchmark.h>

#include <string>

#include "methods/local_global.hpp"
#include "springlab/forces.hpp"
#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"

namespace springlab {
namespace {

Scene cloth(int n) {
  return load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/cloth.json",
                    {"cloth.width=" + std::to_string(n), "cloth.height=" + std::to_string(n)});
}

// The step on an n x n cloth at h = 1 / hz, 10 iterations (XPBD: 1 pass). Args: side, hz, method,
// threads. Counter: steps a second.
void BM_IterativeCloth(benchmark::State& state) {
  Scene s = cloth(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(3)));
  SimulationSettings settings;
  settings.method = static_cast<Method>(state.range(2));
  settings.dt = 1.0 / static_cast<double>(state.range(1));
  Simulation sim(s.model, s.state, settings);
  sim.advance(20);  // past the first fall (and local-global's factorisation)
  for (auto _ : state) sim.step();
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(method_info(settings.method).name);
  set_thread_count(0);
}

constexpr auto kImplicit = static_cast<std::int64_t>(Method::ImplicitEuler);
constexpr auto kXPBD = static_cast<std::int64_t>(Method::XPBD);
constexpr auto kLocalGlobal = static_cast<std::int64_t>(Method::LocalGlobal);
constexpr auto kVBD = static_cast<std::int64_t>(Method::VBD);

// Liu et al.'s curtain: 81 x 81 (6561 vertices), h = 1/30 s. The 64 x 64 cloth at h = 1/60 s.
BENCHMARK(BM_IterativeCloth)
    ->ArgsProduct({{81}, {30}, {kImplicit, kLocalGlobal}, {1, 2}})
    ->ArgsProduct({{64}, {60}, {kImplicit, kXPBD, kLocalGlobal, kVBD}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// Local-global's floor on the same cloths: one local pass and one pair of triangular solves (of
// three right sides at once). Args: side, hz, part (0: both, 1: the local pass, 2: the solves).
void BM_IterativeLocalGlobalFloor(benchmark::State& state) {
  const Scene s = cloth(static_cast<int>(state.range(0)));
  const double h = 1.0 / static_cast<double>(state.range(1));
  Points y;
  std::vector<double> mass;
  iterative::predict(s.model, s.state, h, y, mass);
  LocalGlobalSolver S;
  local_global_parts::factorise(s.model, h, mass, S);
  const int part = static_cast<int>(state.range(2));
  for (auto _ : state) {
    if (part != 2) local_global_parts::global_rhs(s.model, s.state, h, y, y, S);
    if (part != 1) local_global_parts::solve_in_place(S, S.rhs);
    benchmark::ClobberMemory();
  }
  state.counters["factor_nonzeros"] = static_cast<double>(S.factor.matrixL().nestedExpression().nonZeros());
  state.SetLabel(part == 0 ? "local pass + solves" : part == 1 ? "local pass" : "triangular solves");
}
BENCHMARK(BM_IterativeLocalGlobalFloor)
    ->ArgsProduct({{81}, {30}, {0, 1, 2}})
    ->ArgsProduct({{64}, {60}, {0, 1, 2}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace springlab
