// The methods games and films use (XPBD, local-global, vertex block descent) on cloth, each in
// one run beside implicit Euler with conjugate gradients on the same cloth, and local-global's
// floor: one local pass plus one pair of triangular solves, what an iteration cannot go below.
// Run: build/bench/springlab_bench --benchmark_filter=Iterative (figures in docs/performance.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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
// threads. Counters: steps a second, and for implicit Euler its CG iterations a step and a
// second. Always the same 100 steps, 21 to 120: a step's cost follows the cloth's motion (implicit
// Euler's CG takes 140 to 190 iterations a step in the first fall, 60 to 90 by step 100), so a
// count of steps left to the library (it ran 57 or 80 by its first timing) would time different
// steps from one run to the next: 88 against 160 steps/s from the same build.
void BM_IterativeCloth(benchmark::State& state) {
  Scene s = cloth(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(3)));
  SimulationSettings settings;
  settings.method = static_cast<Method>(state.range(2));
  settings.dt = 1.0 / static_cast<double>(state.range(1));
  Simulation sim(s.model, s.state, settings);
  sim.advance(20);  // past local-global's factorisation
  const std::int64_t solver_iterations = sim.counters().solver_iterations;
  for (auto _ : state) sim.step();
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  const double iterations =
      static_cast<double>(sim.counters().solver_iterations - solver_iterations);
  if (settings.method == Method::ImplicitEuler && iterations > 0) {
    state.counters["cg_per_step"] = iterations / static_cast<double>(state.iterations());
    state.counters["cg_per_s"] = benchmark::Counter(iterations, benchmark::Counter::kIsRate);
  }
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
    ->Iterations(100)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// The same triangular solves in single precision (issue 41's item 6: would halving the factor's
// bytes lower the floor?): L's values and D^-1 as floats, the right sides as floats. Not what
// the solver does: its rounding, 1e-7 of the correction against double's 1e-16, would cost
// local-global the momentum it keeps (a free body's, to rounding: momentum_test.cpp).
struct FloatFactor {
  std::vector<float> value, inv_d;
};
FloatFactor single_precision(const LocalGlobalSolver& S) {
  const auto& L = S.factor.matrixL().nestedExpression();
  FloatFactor f;
  f.value.assign(L.valuePtr(), L.valuePtr() + L.nonZeros());
  const Eigen::VectorXd d = S.factor.vectorD();  // (the factor's order; S.inv_d is by place)
  for (Eigen::Index r = 0; r < d.size(); ++r) f.inv_d.push_back(static_cast<float>(1.0 / d[r]));
  return f;
}
void solve_in_place_float(const LocalGlobalSolver& S, const FloatFactor& f, std::vector<float>& z) {
  const auto& L = S.factor.matrixL().nestedExpression();
  local_global_parts::solve_ldlt3(static_cast<int>(L.cols()), L.outerIndexPtr(), L.innerIndexPtr(),
                                  f.value.data(), f.inv_d.data(), z.data());
}

// Local-global's floor on the same cloths: one local pass and one pair of triangular solves (of
// three right sides at once). Args: side, hz, part (0: both, 1: the local pass, 2: the solves,
// 3: the solves in single precision, with their error against the double solve as a counter).
void BM_IterativeLocalGlobalFloor(benchmark::State& state) {
  const Scene s = cloth(static_cast<int>(state.range(0)));
  const double h = 1.0 / static_cast<double>(state.range(1));
  Points y;
  std::vector<double> mass;
  iterative::predict(s.model, s.state, h, y, mass);
  LocalGlobalSolver S;
  local_global_parts::factorise(s.model, h, mass, S);
  const int part = static_cast<int>(state.range(2));
  if (part == 3) {
    local_global_parts::global_rhs(s.model, s.state, h, y, y, S);
    const FloatFactor f = single_precision(S);
    // The right side in the factor's order (the solver keeps it by place: SolvePlan).
    std::vector<double> rhs(S.rhs.size());
    for (int i = 0; i < s.model.particle_count(); ++i)
      if (const int r = S.row[i], q = S.factor_row[i]; r >= 0)
        for (int c = 0; c < 3; ++c) rhs[3 * q + c] = S.rhs[3 * r + c];
    std::vector<float> z(rhs.begin(), rhs.end());
    for (auto _ : state) {
      std::copy(rhs.begin(), rhs.end(), z.begin());
      solve_in_place_float(S, f, z);
      benchmark::ClobberMemory();
    }
    std::vector<double> placed = S.rhs, exact(rhs.size());
    local_global_parts::solve_in_place(S, placed);
    for (int i = 0; i < s.model.particle_count(); ++i)
      if (const int r = S.row[i], q = S.factor_row[i]; r >= 0)
        for (int c = 0; c < 3; ++c) exact[3 * q + c] = placed[3 * r + c];
    double diff = 0.0, size = 0.0;
    for (std::size_t k = 0; k < exact.size(); ++k)
      diff = std::max(diff, std::abs(z[k] - exact[k])), size = std::max(size, std::abs(exact[k]));
    state.counters["relative_error"] = diff / size;
    state.SetLabel("triangular solves, single precision");
    return;
  }
  for (auto _ : state) {
    if (part != 2) local_global_parts::global_rhs(s.model, s.state, h, y, y, S);
    if (part != 1) local_global_parts::solve_in_place(S, S.rhs);
    benchmark::ClobberMemory();
  }
  state.counters["factor_nonzeros"] =
      static_cast<double>(S.factor.matrixL().nestedExpression().nonZeros());
  state.SetLabel(part == 0   ? "local pass + solves"
                 : part == 1 ? "local pass"
                             : "triangular solves");
}
BENCHMARK(BM_IterativeLocalGlobalFloor)
    ->ArgsProduct({{81}, {30}, {0, 1, 2, 3}})
    ->ArgsProduct({{64}, {60}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace springlab
