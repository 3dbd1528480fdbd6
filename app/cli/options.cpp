#include "cli/options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "options/option_ranges.hpp"
#include "springlab/error.hpp"
#include "springlab/forces.hpp"
#include "springlab/iterative_cost.hpp"

namespace springlab::app {

CLI::Validator whole_number(double lo, double hi) {
  std::ostringstream bounds;
  bounds << "[" << lo << ", " << hi << "]";
  return CLI::Validator([lo, hi](std::string& text) { return parse_whole_number(text, lo, hi); },
                        bounds.str());
}

namespace {

// "xpbd: passes over the springs a step (default 1); local-global: ...": from the iterative rows.
std::string iterations_help() {
  std::string help;
  for (const MethodInfo& m : methods())
    if (m.default_iterations > 0)
      help += (help.empty() ? "" : "; ") + std::string(m.name) + ": " +
              (m.iteration_unit ? m.iteration_unit : "iterations") + " a step (default " +
              std::to_string(m.default_iterations) + ")";
  return help;
}

}  // namespace

void add_sim_options(CLI::App& c, SimOptions& o, bool with_length) {
  c.add_option("--method", o.method, "integration method (springlab list shows them)");
  c.add_option("--dt", o.dt, "time step in seconds (default: the scene's)");
  c.add_option("--substeps", o.substeps,
               "integrator steps per step, h = dt / substeps; auto (the default): the fewest that "
               "keep h within "
               "the scene's safe fraction of the method's stability limit");
  if (with_length) {
    c.add_option("--steps", o.steps, "number of steps to simulate")
        ->transform(whole_number(kSteps.lo, kSteps.hi));
    c.add_option("--duration", o.duration, "simulated seconds (default: the scene's)");
  }
  c.add_option("--ks", o.ks, "set every spring's stiffness k_s (N/m)");
  c.add_option("--kd", o.kd, "set every spring's damping k_d (N s/m)");
  c.add_option("--tol", o.tol, "tolerance of the adaptive methods (default: the scene's)");
  c.add_option("--iterations", o.iterations, iterations_help())
      ->transform(whole_number(kIterations.lo, kIterations.hi));
  c.add_option(
      "--rho", o.rho,
      "local-global: Chebyshev acceleration with this spectral radius, in [0, 1) (default 0: off)");
  c.add_option("--set", o.sets, "KEY=VALUE: any other scene field, e.g. cloth.width=64")
      ->allow_extra_args(false);
  c.add_option("--threads", o.threads,
               "threads for the force loops (default: all cores; render and view on a software "
               "rasteriser: 1)")
      ->transform(whole_number(kThreads.lo, kThreads.hi));
}

// Local-global's Chebyshev acceleration past the plain iteration's own radius (iterative_cost.hpp).
void warn_if_rho_past_radius(const Simulation& sim, const std::string& scene) {
  const double rho = sim.settings().step.chebyshev_rho;
  if (!method_info(sim.settings().method).reads_rho || !(rho > 0.0)) return;
  const double radius = local_global_radius(sim.model(), sim.state(), sim.h());
  if (rho <= radius) return;
  std::fprintf(stderr,
               "springlab: warning: %s: --rho %.4g is past local-global's spectral radius here, "
               "%.4g (measured at h = "
               "%.4g s): Chebyshev acceleration then overshoots each step and can put energy in; "
               "use --rho %.3g or "
               "less\n",
               scene.c_str(), rho, radius, sim.h(), std::floor(radius * 1000.0) / 1000.0);
}

void warn_if_unstable(Simulation& sim, const std::string& scene) {
  warn_if_rho_past_radius(sim, scene);
  const StabilityLimit& limit =
      sim.stability_limit();  // (made now: with automatic sub-steps, chooses them)
  if (!std::isfinite(limit.h) || sim.h() <= limit.h) return;
  if (limit.h == 0.0) {
    std::fprintf(stderr,
                 "springlab: warning: %s: %s is unstable at any step here (not enough damping): "
                 "use a method "
                 "that is stable without damping (symplectic-euler, verlet, rk4, implicit-euler) "
                 "or add damping\n",
                 scene.c_str(), method_info(sim.settings().method).name);
    return;
  }
  const std::string method = method_info(sim.settings().method).name;
  if (sim.auto_substeps()) {
    std::fprintf(stderr,
                 "springlab: warning: %s: the automatic sub-steps reached their cap (%d), and h = "
                 "%.4g s is still "
                 "past %s's %s (%.4g s); it will most likely go unstable: use a smaller --dt or a "
                 "more stable "
                 "--method (implicit-euler)\n",
                 scene.c_str(), kMaxAutoSubsteps, sim.h(), method.c_str(),
                 limit.exact ? "stability limit" : "proven stable step", limit.h);
    return;
  }
  const double substeps = std::ceil(sim.h() / (0.9 * limit.h)) * sim.settings().substeps;
  char fix[96];
  if (substeps <= kSubsteps.hi)
    std::snprintf(fix, sizeof fix, "--substeps %.0f (or auto) or --dt %.3g", substeps,
                  0.9 * limit.h * sim.settings().substeps);
  else
    std::snprintf(fix, sizeof fix, "--dt %.3g or a more stable --method (implicit-euler)",
                  0.9 * limit.h * sim.settings().substeps);
  std::fprintf(
      stderr,
      "springlab: warning: %s: h = %.4g s is past %s's %s (%.4g s, h w_max = %.3g); %s: use %s\n",
      scene.c_str(), sim.h(), method.c_str(),
      limit.exact ? "stability limit" : "proven stable step (the exact limit may be higher)",
      limit.h, sim.h() * sim.stability().w_max(),
      limit.exact ? "it will most likely diverge" : "it may diverge", fix);
}

}  // namespace springlab::app
