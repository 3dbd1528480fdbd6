#include "options/scene_options.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "options/option_ranges.hpp"
#include "springlab/error.hpp"
#include "springlab/forces.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

std::string parse_whole_number(std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && *end == '\0';
  if (number && std::isfinite(x) && x == std::floor(x) && x >= lo && x <= hi) {
    text = std::to_string(static_cast<long long>(x));  // "1e6" reads as 1000000
    return "";
  }
  std::ostringstream s;
  s << "must be a whole number in [" << lo << ", " << hi << "], got ";
  if (number)
    s << x;
  else
    s << "'" << text << "'";
  return s.str();
}

std::vector<Method> parse_method_list(const std::string& text, const char* option) {
  std::vector<Method> list;
  std::stringstream s(text);
  for (std::string name; std::getline(s, name, ',');) {
    const auto m = lookup_method(name);
    if (!m)
      throw InputError(std::string(option) + ": unknown method '" + name + "' (" +
                       method_choices() + ")");
    list.push_back(*m);
  }
  return list;
}

void check_option(const char* name, double value, double lo, double hi, bool lo_open,
                  const char* unit) {
  if (std::isfinite(value) && (lo_open ? value > lo : value >= lo) && value <= hi) return;
  std::ostringstream s;
  s << name << ": must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]" << unit
    << ", got " << value;
  throw InputError(s.str());
}

Method resolve_method(const std::string& name) {
  if (const auto method = lookup_method(name)) return *method;
  std::vector<std::string> names;
  for (const auto& m : methods()) names.emplace_back(m.name);
  for (const auto& t : shipped_tableaux()) names.push_back(t);
  const std::string near = closest_match(name, names.data(), names.size());
  throw InputError("--method: unknown method '" + name + "'" +
                   (near.empty() ? "" : "; did you mean '" + near + "'?") + " (" +
                   method_choices() + ")");
}

void require_integration(const Scene& scene, const char* command) {
  if (scene.ik)
    throw InputError(std::string(command) + ": '" + scene.name +
                     "' is an inverse-kinematics scene, which has no "
                     "integrator to measure; use `springlab run " +
                     scene.name +
                     "` (each solver's result), "
                     "`view` or `render`");
}

Prepared prepare(const std::string& scene_name, const SimOptions& o) {
  Prepared p;
  // Options first: a bad option is reported before any file is read.
  if (o.dt) check_option("--dt", *o.dt, 0.0, 1.0, true, " s");
  std::optional<int> substeps;  // fixed; none: automatic
  if (o.substeps && *o.substeps != "auto") {
    std::string text = *o.substeps;
    const std::string error = parse_whole_number(text, kSubsteps.lo, kSubsteps.hi);
    if (!error.empty()) throw InputError("--substeps: " + error + " (or auto)");
    substeps = std::stoi(text);
  }
  if (o.steps) check_option("--steps", static_cast<double>(*o.steps), kSteps.lo, kSteps.hi, false);
  if (o.duration) check_option("--duration", *o.duration, 0.0, 1e7, true, " s");
  if (o.ks) check_option("--ks", *o.ks, 0.0, 1e12, false, " N/m");
  if (o.kd) check_option("--kd", *o.kd, 0.0, 1e12, false, " N s/m");
  if (o.tol) check_option("--tol", *o.tol, 0.0, 1.0, true);
  if (o.threads) check_option("--threads", *o.threads, kThreads.lo, kThreads.hi, false);
  if (o.iterations)
    check_option("--iterations", *o.iterations, kIterations.lo, kIterations.hi, false);
  if (o.rho && !(*o.rho >= 0.0 && *o.rho < 1.0)) {
    std::ostringstream s;
    s << "--rho: must be in [0, 1) (local-global's Chebyshev acceleration; 0: off), got " << *o.rho;
    throw InputError(s.str());
  }
  std::optional<Method> method;
  if (o.method) method = resolve_method(*o.method);

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
  if (o.iterations) p.settings.step.iterations = *o.iterations;
  if (o.rho) p.settings.step.chebyshev_rho = *o.rho;
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
  p.steps =
      o.steps ? *o.steps : static_cast<std::int64_t>(std::ceil(duration / p.settings.dt - 1e-9));
  if (p.steps < 1) p.steps = 1;
  return p;
}

}  // namespace springlab::app
