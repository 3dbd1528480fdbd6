// springlab bench SCENE: the scene's step throughput with a method, without graphics, after a
// warm-up; one key=value a line (substeps and whether chosen, particles, springs, steps, seconds,
// steps_per_s, ns_per_spring_step, peak_rss_mb, and for implicit methods solver_iterations_per_step
// and unconverged_solves), for scripts and docs/performance.md's figures. With --repeat N the steps
// are timed N times over (the simulation going on: the same work each time for the explicit
// methods; an implicit method's solves get cheaper as a scene settles): the figures are the fastest
// run's, and ns_per_spring_step_median is the middle one, since on a machine whose speed wanders (a
// shared or throttled core) one run says little.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "springlab/error.hpp"
#include "springlab/forces.hpp"

namespace springlab::app {

namespace {

struct BenchOptions {
  std::string scene;
  SimOptions sim;
  int repeat = 1;
};

int bench(const BenchOptions& o) {
  SimOptions sim = o.sim;
  if (!sim.steps && !sim.duration) sim.steps = 1000;
  Prepared p = prepare(o.scene, sim);
  require_integration(p.scene, "bench");
  Simulation s(std::move(p.scene.model), std::move(p.scene.state), p.settings);
  // Warm-up: caches, the first allocations, the implicit solver's pattern.
  const std::int64_t warm = std::max<std::int64_t>(1, p.steps / 10);
  s.advance(warm);
  std::vector<double> runs;  // seconds of each timed run
  std::int64_t taken = 0;
  for (int run = 0; run < o.repeat; ++run) {
    const auto start = std::chrono::steady_clock::now();
    taken = s.advance(p.steps);
    runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    // A diverged run's figures would time a state of NaNs and infinities: report it instead.
    if (s.diverged()) {
      std::fprintf(stderr, "springlab: %s: %s\n", p.scene.name.c_str(),
                   s.explain_divergence()->message().c_str());
      return kDiverged;
    }
  }
  std::sort(runs.begin(), runs.end());
  const double seconds = runs.front();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double springs = s.model().spring_count();
  const auto ns_per_spring_step = [&](double time) {
    return springs > 0 ? 1e9 * time / (taken * s.settings().substeps * springs) : 0.0;
  };
  std::printf(
      "scene=%s\nmethod=%s\nthreads=%d\nsubsteps=%d\nsubsteps_auto=%d\nparticles=%d\nsprings=%d\n"
      "steps=%lld\nseconds=%.6g\nsteps_per_s=%.6g\nns_per_spring_step=%.4g\npeak_rss_mb=%.1f\n",
      p.scene.name.c_str(), method_info(p.settings.method).name, thread_count(),
      s.settings().substeps, s.auto_substeps() ? 1 : 0, s.model().particle_count(),
      s.model().spring_count(), static_cast<long long>(taken), seconds, taken / seconds,
      ns_per_spring_step(seconds), static_cast<double>(usage.ru_maxrss) / 1024.0);
  const TeamCounts team = team_counts();  // the warm-up's too
  std::printf("team_passes=%ld\nalone_passes=%ld\nyielding_waits=%ld\nstalled_runs=%ld\n",
              team.team, team.alone, team.yields, team.stalls);
  if (o.repeat > 1)  // the middle run (the mean of the two middle ones for an even count)
    std::printf("repeats=%d\nns_per_spring_step_median=%.4g\n", o.repeat,
                ns_per_spring_step(0.5 * (runs[(runs.size() - 1) / 2] + runs[runs.size() / 2])));
  if (s.counters().linear_solves > 0)  // over all steps, the warm-up's too
    std::printf("solver_iterations_per_step=%.4g\nunconverged_solves=%lld\n",
                static_cast<double>(s.counters().solver_iterations) / s.counters().linear_solves,
                static_cast<long long>(s.counters().unconverged_solves));
  return kOk;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* c =
      app.add_subcommand("bench", "step throughput of a scene and method (key=value lines)");
  c->add_option("scene", o->scene, "scene name or JSON file")->required();
  add_sim_options(*c, o->sim);
  c->add_option(
       "--repeat", o->repeat,
       "time the steps this many times over (the simulation going on: for the explicit methods the "
       "same work each time); the figures are the fastest run's")
      ->transform(whole_number(1, 1000));
  return [o] { return bench(*o); };
}

}  // namespace springlab::app
