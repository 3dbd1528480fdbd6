#include "cli/options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "springlab/error.hpp"
#include "springlab/forces.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace {
// The integer options' ranges: checked as the text is read, and again in prepare().
struct WholeRange {
  double lo, hi;
};
constexpr WholeRange kSubsteps{1, 100000}, kSteps{1, 1e12}, kThreads{0, 1024};
}  // namespace

CLI::Validator whole_number(double lo, double hi) {
  std::ostringstream bounds;
  bounds << "[" << lo << ", " << hi << "]";
  const std::string range = bounds.str();
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && *end == '\0';
        if (number && std::isfinite(x) && x == std::floor(x) && x >= lo && x <= hi) {
          text = std::to_string(static_cast<long long>(x));  // "1e6" reads as 1000000
          return "";
        }
        std::ostringstream s;
        s << "must be a whole number in " << range << ", got ";
        if (number) s << x;
        else s << "'" << text << "'";
        return s.str();
      },
      range);
}

void add_sim_options(CLI::App& c, SimOptions& o, bool with_length) {
  c.add_option("--method", o.method, "integration method (springlab list shows them)");
  c.add_option("--dt", o.dt, "time step in seconds (default: the scene's)");
  c.add_option("--substeps", o.substeps,
               "integrator steps per step, h = dt / substeps; auto (the default): the fewest that keep h within "
               "the scene's safe fraction of the method's stability limit");
  if (with_length) {
    c.add_option("--steps", o.steps, "number of steps to simulate")
        ->transform(whole_number(kSteps.lo, kSteps.hi));
    c.add_option("--duration", o.duration, "simulated seconds (default: the scene's)");
  }
  c.add_option("--ks", o.ks, "set every spring's stiffness k_s (N/m)");
  c.add_option("--kd", o.kd, "set every spring's damping k_d (N s/m)");
  c.add_option("--tol", o.tol, "tolerance of the adaptive methods (default: the scene's)");
  c.add_option("--set", o.sets, "KEY=VALUE: any other scene field, e.g. cloth.width=64")
      ->allow_extra_args(false);
  c.add_option("--threads", o.threads, "threads for the force loops (default: all cores; render and view on a software rasteriser: 1)")
      ->transform(whole_number(kThreads.lo, kThreads.hi));
}

void warn_if_unstable(Simulation& sim, const std::string& scene) {
  const StabilityLimit& limit = sim.stability_limit();  // (made now: with automatic sub-steps, chooses them)
  if (!std::isfinite(limit.h) || sim.h() <= limit.h) return;
  if (limit.h == 0.0) {
    std::fprintf(stderr, "springlab: warning: %s: %s is unstable at any step here (not enough damping): use a method "
                 "that is stable without damping (symplectic-euler, verlet, rk4, implicit-euler) or add damping\n",
                 scene.c_str(), method_info(sim.settings().method).name);
    return;
  }
  const std::string method = method_info(sim.settings().method).name;
  if (sim.auto_substeps()) {
    std::fprintf(stderr,
                 "springlab: warning: %s: the automatic sub-steps reached their cap (%d), and h = %.4g s is still "
                 "past %s's %s (%.4g s); it will most likely go unstable: use a smaller --dt or a more stable "
                 "--method (implicit-euler)\n",
                 scene.c_str(), kMaxAutoSubsteps, sim.h(), method.c_str(),
                 limit.exact ? "stability limit" : "proven stable step", limit.h);
    return;
  }
  const double substeps = std::ceil(sim.h() / (0.9 * limit.h)) * sim.settings().substeps;
  char fix[96];
  if (substeps <= kSubsteps.hi)
    std::snprintf(fix, sizeof fix, "--substeps %.0f (or auto) or --dt %.3g", substeps, 0.9 * limit.h * sim.settings().substeps);
  else
    std::snprintf(fix, sizeof fix, "--dt %.3g or a more stable --method (implicit-euler)", 0.9 * limit.h * sim.settings().substeps);
  std::fprintf(stderr, "springlab: warning: %s: h = %.4g s is past %s's %s (%.4g s, h w_max = %.3g); %s: use %s\n",
               scene.c_str(), sim.h(), method.c_str(),
               limit.exact ? "stability limit" : "proven stable step (the exact limit may be higher)", limit.h,
               sim.h() * sim.stability().w_max(), limit.exact ? "it will most likely diverge" : "it may diverge", fix);
}

void check_option(const char* name, double value, double lo, double hi, bool lo_open,
                  const char* unit) {
  if (std::isfinite(value) && (lo_open ? value > lo : value >= lo) && value <= hi) return;
  std::ostringstream s;
  s << name << ": must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]" << unit
    << ", got " << value;
  throw InputError(s.str());
}

Prepared prepare(const std::string& scene_name, const SimOptions& o) {
  Prepared p;
  // Options first: a bad option is reported before any file is read.
  if (o.dt) check_option("--dt", *o.dt, 0.0, 1.0, true, " s");
  std::optional<int> substeps;  // fixed; none: automatic
  if (o.substeps && *o.substeps != "auto") {
    std::string text = *o.substeps;
    const std::string error = whole_number(kSubsteps.lo, kSubsteps.hi)(text);
    if (!error.empty()) throw InputError("--substeps: " + error + " (or auto)");
    substeps = std::stoi(text);
  }
  if (o.steps) check_option("--steps", static_cast<double>(*o.steps), kSteps.lo, kSteps.hi, false);
  if (o.duration) check_option("--duration", *o.duration, 0.0, 1e7, true, " s");
  if (o.ks) check_option("--ks", *o.ks, 0.0, 1e12, false, " N/m");
  if (o.kd) check_option("--kd", *o.kd, 0.0, 1e12, false, " N s/m");
  if (o.tol) check_option("--tol", *o.tol, 0.0, 1.0, true);
  if (o.threads) check_option("--threads", *o.threads, kThreads.lo, kThreads.hi, false);
  std::optional<Method> method;
  if (o.method) {
    method = find_method(*o.method);
    if (!method) {
      std::vector<std::string> names;
      for (const auto& m : methods()) names.emplace_back(m.name);
      const std::string near = closest_match(*o.method, names.data(), names.size());
      throw InputError("--method: unknown method '" + *o.method + "'" +
                       (near.empty() ? "" : "; did you mean '" + near + "'?") +
                       " (methods: " + method_names() + ")");
    }
  }

  p.scene = load_scene(resolve_scene(scene_name), o.sets);
  Scene& s = p.scene;
  if (o.ks) set_stiffness(s.model, *o.ks);
  if (o.kd) set_damping(s.model, *o.kd);
  if (o.threads) set_thread_count(*o.threads);

  p.settings = settings_for(s);
  if (method) p.settings.method = *method;
  p.settings.dt = o.dt ? *o.dt : s.dt;
  // Sub-steps: fixed by --substeps N or by the scene's file, else chosen from the stability
  // limit (with the scene's safe fraction) when the simulation first steps.
  if (substeps) {
    p.settings.auto_substeps = false;
    p.settings.substeps = *substeps;
  }
  p.settings.step.tolerance = o.tol ? *o.tol : s.tolerance;
  const double duration = o.duration ? *o.duration : s.duration;
  if (!o.steps) {
    // Checked before the conversion: a tiny dt ("dt": 1e-300) made a count no integer holds.
    const double steps = std::ceil(duration / p.settings.dt - 1e-9);
    if (!(steps <= kSteps.hi)) {
      std::ostringstream m;
      m << "scene '" << s.file << "': a duration of " << duration << " s at dt = " << p.settings.dt
        << " s would take " << steps << " steps; the limit is " << kSteps.hi
        << ": use a larger --dt, a shorter --duration, or --steps";
      throw InputError(m.str());
    }
  }
  p.steps = o.steps ? *o.steps
                    : static_cast<std::int64_t>(std::ceil(duration / p.settings.dt - 1e-9));
  if (p.steps < 1) p.steps = 1;
  return p;
}

void require_integration(const Scene& scene, const char* command) {
  if (scene.ik)
    throw InputError(std::string(command) + ": '" + scene.name + "' is an inverse-kinematics scene, which has no "
                     "integrator to measure; use `springlab run " + scene.name + "` (each solver's result), "
                     "`view` or `render`");
}

}  // namespace springlab::app
