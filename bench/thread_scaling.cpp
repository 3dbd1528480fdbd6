// Steps a second of one solver at each of several thread counts, with the core alone (no window,
// no GL: it links statically and runs on any x86-64 Linux, the lent 16-core machine included).
// docs/performance.md's scaling and load tables come from it (scripts/load-bench.sh,
// scripts/scaling.sh).
//
//   springlab_threads SCENE_FILE METHOD DT STEPS THREADS... [--set KEY=VALUE]... [--analysis]
//
// For each thread count: a warm-up of STEPS / 10 steps, then STEPS timed steps; one line
// "threads=T steps_per_s=S team=J alone=A yields=Y stalls=R shared=C sleeps=Z". With --analysis,
// the scene's stability analysis is timed instead: "threads=T analysis_s=S".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "springlab/forces.hpp"
#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"
#include "springlab/stability.hpp"

using namespace springlab;

namespace {

// The whole argument as a number in [lo, hi] (a whole one if `whole`), or an error naming it:
// atof would read "1/60" as 1 and time the wrong step without a word.
double number(const char* what, const char* text, double lo, double hi, bool whole,
              const char* hint = "") {
  char* end = nullptr;
  const double x = std::strtod(text, &end);
  if (end != text && *end == '\0' && x >= lo && x <= hi && (!whole || x == std::floor(x))) return x;
  char message[256];
  std::snprintf(message, sizeof message, "%s must be a %s in [%g, %g], got '%s'%s", what,
                whole ? "whole number" : "number", lo, hi, text, hint);
  throw std::invalid_argument(message);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(
        stderr,
        "usage: %s SCENE_FILE METHOD DT STEPS THREADS... [--set KEY=VALUE]... [--analysis]\n",
        argv[0]);
    return 2;
  }
  try {
    std::vector<std::string> overrides;
    std::vector<int> thread_counts;
    bool analysis = false;
    for (int a = 5; a < argc; ++a) {
      const std::string arg = argv[a];
      if (arg == "--set" && a + 1 < argc)
        overrides.push_back(argv[++a]);
      else if (arg == "--analysis")
        analysis = true;
      else
        thread_counts.push_back(
            static_cast<int>(number("THREADS", argv[a], 0, 4096, true, " (0: the default)")));
    }
    const Scene scene = load_scene(argv[1], overrides);
    const std::optional<Method> method = find_method(argv[2]);
    if (!method) {
      std::fprintf(stderr, "unknown method '%s'\n", argv[2]);
      return 2;
    }
    const double dt =
        number("DT", argv[3], 1e-12, 1e6, false, " (seconds: 1/60 s is 0.016666666666666666)");
    const long steps = static_cast<long>(number("STEPS", argv[4], 1, 1e12, true));
    for (int threads : thread_counts) {
      set_thread_count(threads);
      if (analysis) {
        const auto start = std::chrono::steady_clock::now();
        const StabilityAnalysis a(scene.model, scene.state);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("threads=%d analysis_s=%.4g w_max=%.6g\n", threads, s, a.w_max());
        std::fflush(stdout);
        continue;
      }
      SimulationSettings settings;
      settings.method = *method;
      settings.dt = dt;
      settings.substeps = 1;
      settings.auto_substeps = false;
      Simulation sim(scene.model, scene.state, settings);
      sim.advance(std::max(1L, steps / 10));
      const TeamCounts before = team_counts();
      const auto start = std::chrono::steady_clock::now();
      const long taken = static_cast<long>(sim.advance(steps));
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const TeamCounts after = team_counts();
      if (sim.diverged()) {
        std::fprintf(stderr, "diverged: %s\n", sim.explain_divergence()->message().c_str());
        return 3;
      }
      std::printf(
          "threads=%d steps_per_s=%.5g team=%ld alone=%ld yields=%ld stalls=%ld shared=%ld "
          "sleeps=%ld\n",
          threads, taken / s, after.team - before.team, after.alone - before.alone,
          after.yields - before.yields, after.stalls - before.stalls, after.shared - before.shared,
          after.sleeps - before.sleeps);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
