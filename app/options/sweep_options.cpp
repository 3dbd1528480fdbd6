#include "options/sweep_options.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "springlab/error.hpp"

namespace springlab::app {

namespace {

// "LO:HI" with 0 < LO < HI <= max.
std::pair<double, double> range(const std::string& option, const std::string& text, double max) {
  const auto colon = text.find(':');
  char* end1 = nullptr;
  char* end2 = nullptr;
  const std::string a = text.substr(0, colon),
                    b = colon == std::string::npos ? "" : text.substr(colon + 1);
  const double lo = std::strtod(a.c_str(), &end1), hi = std::strtod(b.c_str(), &end2);
  if (colon == std::string::npos || a.empty() || b.empty() || *end1 || *end2 || !(lo > 0) ||
      !(hi > lo) || !(hi <= max))
    throw InputError(option +
                     ": must be LO:HI with 0 < LO < HI <= " + std::to_string(max).substr(0, 4) +
                     ", for example 0.001:0.02; got '" + text + "'");
  return {lo, hi};
}

}  // namespace

PreparedSweep prepare_sweep(const std::string& scene, const SimOptions& sim,
                            const SweepOptions& o) {
  if (o.points < 2 || o.points > 64)
    throw InputError("--points: must be in [2, 64], got " + std::to_string(o.points));
  if (o.repeats < 1 || o.repeats > 100)
    throw InputError("--repeats: must be in [1, 100], got " + std::to_string(o.repeats));
  std::vector<Method> list;
  if (o.methods) list = parse_method_list(*o.methods, "--methods");
  PreparedSweep out{prepare(scene, sim), {}};
  const Prepared& p = out.prepared;
  require_integration(p.scene, "compare");
  SweepSettings& s = out.settings;
  s.methods = list;
  s.points = o.points;
  s.repeats = o.repeats;
  s.step = p.settings.step;
  s.workers = sim.threads.value_or(0);
  const double dt = p.settings.dt;
  std::tie(s.h_min, s.h_max) =
      o.dt_range ? range("--dt-range", *o.dt_range, 1.0) : std::pair{dt / 16, dt * 2};
  if (o.tol_range) std::tie(s.tol_min, s.tol_max) = range("--tol-range", *o.tol_range, 1.0);
  s.duration = sim.duration ? *sim.duration : std::min(p.scene.duration, 2.0);
  if (s.duration < s.h_max) {
    char largest[32];
    std::snprintf(largest, sizeof largest, "%.4g s", s.h_max);
    throw InputError(std::string("--duration: must be at least the largest step (") + largest +
                     ")");
  }
  s.drift_h = dt;
  s.drift_substeps = p.settings.substeps;
  s.drift_auto_substeps = p.settings.auto_substeps;
  s.drift_safety = p.settings.safety;
  if (o.drift_duration) check_option("--drift-duration", *o.drift_duration, 0.0, 1e6, false, " s");
  s.drift_duration = o.drift_duration ? *o.drift_duration : p.scene.duration;
  check_option("--stability-budget", o.stability_budget, 0.0, 1e13, false);
  s.stability = o.stability_budget > 0.0;
  s.stability_budget = o.stability_budget;
  return out;
}

}  // namespace springlab::app
