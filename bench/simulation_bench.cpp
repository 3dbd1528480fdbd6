// Benchmarks of the simulation core (Google Benchmark): the spring kernel and the force pass,
// each method's step on rope and cloth at several sizes and thread counts, the implicit solve,
// building scenes, and the stability estimate. Run: build/bench/springlab_bench
// (docs/performance.md has the figures).
#include <benchmark/benchmark.h>

#include <Eigen/SparseCholesky>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "springlab/forces.hpp"
#include "springlab/methods.hpp"
#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"
#include "springlab/spring_kernel.hpp"
#include "springlab/stability.hpp"

namespace springlab {
namespace {

Scene cloth(int n) {
  return load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/cloth.json",
                    {"cloth.width=" + std::to_string(n), "cloth.height=" + std::to_string(n)});
}

Scene rope(int nodes) {
  return load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/rope.json",
                    {"rope.nodes=" + std::to_string(nodes)});
}

using Clock = std::chrono::steady_clock;

// The counters every step benchmark reports: springs, and wall-clock nanoseconds per spring per
// iteration since `start` (taken just before the timed loop).
void per_spring(benchmark::State& state, const Model& model, Clock::time_point start) {
  const double springs = model.spring_count();
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
  state.counters["springs"] = springs;
  state.counters["ns_per_spring"] = ns / (static_cast<double>(state.iterations()) * springs);
}

// One spring's force with the scalar kernel (the reference the vector loop agrees with).
void BM_SpringKernel(benchmark::State& state) {
  const Vec3 a(0, 0, 0), b(1.1, 0.2, -0.3), va(0, 1, 0), vb(0.5, 0, 0);
  for (auto _ : state) benchmark::DoNotOptimize(spring_force(a, b, va, vb, 100.0, 0.5, 1.0));
}
BENCHMARK(BM_SpringKernel);

// One force evaluation of a cloth: args are the side and the thread count.
void BM_Forces(benchmark::State& state) {
  const Scene s = cloth(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(1)));
  Points a;
  SpringForces buffer;
  const Clock::time_point start = Clock::now();
  for (auto _ : state) {
    evaluate_forces(s.model, s.state.x, s.state.v, a, buffer, ForceOutput::Acceleration);
    benchmark::ClobberMemory();
  }
  per_spring(state, s.model, start);
  set_thread_count(0);
}
BENCHMARK(BM_Forces)->ArgsProduct({{32, 64, 128, 256}, {1, 2}})->UseRealTime();

// A simulation step (with its checks) of a method on a cloth: side, threads, method.
void BM_ClothStep(benchmark::State& state) {
  Scene s = cloth(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(1)));
  SimulationSettings settings;
  settings.method = static_cast<Method>(state.range(2));
  settings.dt = 1e-5;  // small enough for every explicit method at every size
  Simulation sim(s.model, s.state, settings);
  sim.advance(5);
  const Clock::time_point start = Clock::now();
  for (auto _ : state) sim.step();
  per_spring(state, s.model, start);
  state.SetLabel(method_info(settings.method).name);
  set_thread_count(0);
}

// Every explicit method of the one table (implicit Euler has BM_ImplicitCloth, the iterative
// methods BM_IterativeCloth in iterative_bench.cpp).
std::vector<std::int64_t> explicit_methods() {
  std::vector<std::int64_t> ids;
  for (const MethodInfo& m : methods())
    if (!m.any_step()) ids.push_back(static_cast<std::int64_t>(m.id));
  return ids;
}

BENCHMARK(BM_ClothStep)->ArgsProduct({{32, 64, 128}, {1, 2}, explicit_methods()})->UseRealTime();

// The implicit step on cloth at one step a frame (h = 1/60): a force evaluation, the springs'
// blocks and the matrix-free conjugate-gradient solve at the default tolerance. Args: side,
// threads. Counters: iterations a step and unconverged solves, over the timed steps.
void BM_ImplicitCloth(benchmark::State& state) {
  Scene s = cloth(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(1)));
  SimulationSettings settings;
  settings.method = Method::ImplicitEuler;
  settings.dt = 1.0 / 60.0;
  Simulation sim(s.model, s.state, settings);
  sim.advance(20);  // as springlab bench: past the first fall, which takes more iterations
  const Counters before = sim.counters();
  const Clock::time_point start = Clock::now();
  for (auto _ : state) sim.step();
  per_spring(state, s.model, start);
  const Counters& after = sim.counters();
  const double solves = static_cast<double>(after.linear_solves - before.linear_solves);
  state.counters["cg_iterations_per_step"] =
      static_cast<double>(after.solver_iterations - before.solver_iterations) / solves;
  state.counters["unconverged"] =
      static_cast<double>(after.unconverged_solves - before.unconverged_solves);
  char label[32];
  std::snprintf(label, sizeof label, "tolerance %.0e", settings.step.solver_tolerance);
  state.SetLabel(label);
  set_thread_count(0);
}
BENCHMARK(BM_ImplicitCloth)
    ->ArgsProduct({{32, 64}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// A rope's step: nodes, threads, method.
void BM_RopeStep(benchmark::State& state) {
  Scene s = rope(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(1)));
  SimulationSettings settings;
  settings.method = static_cast<Method>(state.range(2));
  settings.dt = 1e-7;
  Simulation sim(s.model, s.state, settings);
  sim.advance(5);
  const Clock::time_point start = Clock::now();
  for (auto _ : state) sim.step();
  per_spring(state, s.model, start);
  state.SetLabel(method_info(settings.method).name);
  set_thread_count(0);
}
BENCHMARK(BM_RopeStep)
    ->ArgsProduct({{100, 1000, 10000}, {1, 2}, explicit_methods()})
    ->UseRealTime();

// Building a scene from its file: parsing, checking, generating, sorting springs into spans.
void BM_BuildScene(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(cloth(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_BuildScene)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

// The stability analysis (stability.hpp: the equilibrium, then every method's limit from the
// joint numerical range, the definiteness tests and, on small scenes, every eigenvalue): what
// `run`, the divergence messages and the app's gauge wait for when a scene is loaded. Arguments:
// a rope's nodes (0: a cloth), a cloth's side, and the threads (0: all; the analysis's searches
// run on them side by side). BM_StabilityAtRest starts from the equilibrium (the analysis alone).
Scene analysed_scene(const benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0)), side = static_cast<int>(state.range(1));
  return nodes > 0 ? rope(nodes) : cloth(side);
}
std::string analysed_label(const benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0)), side = static_cast<int>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  return (nodes > 0 ? "rope " + std::to_string(nodes)
                    : "cloth " + std::to_string(side) + "x" + std::to_string(side)) +
         ", " +
         (threads > 0 ? std::to_string(threads) + " thread" + (threads > 1 ? "s" : "")
                      : "all threads");
}
void analysis_arguments(benchmark::internal::Benchmark* b) {
  for (int threads : {1, 0}) {
    b->Args({1000, 0, threads});
    b->Args({0, 64, threads});
    b->Args({0, 80, threads});  // (between the two targets: 7.3 s until stop 38, Newton's fallback)
    b->Args({0, 128, threads});
  }
  b->Unit(benchmark::kMillisecond);
}

void BM_StabilityAnalysis(benchmark::State& state) {
  const Scene s = analysed_scene(state);
  const int before = thread_count();
  set_thread_count(static_cast<int>(state.range(2)));
  int dofs = 0;
  for (auto _ : state) dofs = StabilityAnalysis(s.model, s.state).dofs();
  set_thread_count(before);
  state.counters["dofs"] = dofs;
  state.SetLabel(analysed_label(state));
}
BENCHMARK(BM_StabilityAnalysis)->Apply(analysis_arguments);

void BM_StabilityAtRest(benchmark::State& state) {
  const Scene s = analysed_scene(state);
  const State rest = equilibrium(s.model, s.state);
  const int before = thread_count();
  set_thread_count(static_cast<int>(state.range(2)));
  for (auto _ : state) benchmark::DoNotOptimize(StabilityAnalysis(s.model, rest).w_max());
  set_thread_count(before);
  state.SetLabel(analysed_label(state));
}
BENCHMARK(BM_StabilityAtRest)->Apply(analysis_arguments);

// The floor under the analysis's Newton steps (docs/performance.md, "The stability analysis"): one
// sparse LDL^T factorisation of a cloth's stiffness at its balance plus a small mu M, as
// equilibrium.cpp makes it (Eigen's SimplicialLDLT, the ordering found once, outside the timing).
void BM_BalanceFactorisation(benchmark::State& state) {
  const Scene s = cloth(static_cast<int>(state.range(0)));
  const Model& m = s.model;
  const State rest = equilibrium(m, s.state);
  std::vector<int> index(m.particle_count(), -1);
  int free = 0;
  for (int i = 0; i < m.particle_count(); ++i)
    if (!m.pinned(i)) index[i] = free++;
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < m.spring_count(); ++k) {
    const int ends[2] = {index[m.spring_a[k]], index[m.spring_b[k]]};
    const Eigen::Matrix3d block =
        spring_jacobian(rest.x.row(m.spring_a[k]).transpose(),
                        rest.x.row(m.spring_b[k]).transpose(), Vec3::Zero(), Vec3::Zero(), m.ks(k),
                        0.0, m.rest_length[k], false)
            .dfdx;
    for (int p = 0; p < 2; ++p)
      for (int q = 0; q < 2; ++q)
        if (ends[p] >= 0 && ends[q] >= 0)
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
              t.emplace_back(3 * ends[p] + r, 3 * ends[q] + c, (p == q ? 1.0 : -1.0) * block(r, c));
  }
  for (int i = 0; i < m.particle_count(); ++i)
    if (index[i] >= 0)
      for (int c = 0; c < 3; ++c)
        t.emplace_back(3 * index[i] + c, 3 * index[i] + c, 1e-3 * m.mass[i]);
  Eigen::SparseMatrix<double> A(3 * free, 3 * free);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  solver.analyzePattern(A);
  for (auto _ : state) solver.factorize(A);
  state.counters["dofs"] = 3 * free;
}
BENCHMARK(BM_BalanceFactorisation)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace springlab

namespace springlab {
namespace {
// One force evaluation of a rope (a single long span): nodes, threads.
void BM_RopeForces(benchmark::State& state) {
  const Scene s = rope(static_cast<int>(state.range(0)));
  set_thread_count(static_cast<int>(state.range(1)));
  Points a;
  SpringForces buffer;
  const Clock::time_point start = Clock::now();
  for (auto _ : state) {
    evaluate_forces(s.model, s.state.x, s.state.v, a, buffer, ForceOutput::Acceleration);
    benchmark::ClobberMemory();
  }
  per_spring(state, s.model, start);
  set_thread_count(0);
}
BENCHMARK(BM_RopeForces)->ArgsProduct({{1000, 24000}, {1, 2}})->UseRealTime();
}  // namespace
}  // namespace springlab

BENCHMARK_MAIN();
