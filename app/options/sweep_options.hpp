// The options of an accuracy-against-cost sweep (`springlab compare` and the Python module's
// sweep()) turned into the core's SweepSettings (springlab/sweep.hpp), every value checked: one
// place, so that both sweep the same steps and give the same messages.
#pragma once

#include <optional>
#include <string>

#include "options/scene_options.hpp"
#include "springlab/sweep.hpp"

namespace springlab::app {

struct SweepOptions {
  std::optional<std::string> methods;    // "euler,rk4" (default: every method)
  std::optional<std::string> dt_range;   // "LO:HI" (default: dt / 16 to 2 dt)
  std::optional<std::string> tol_range;  // "LO:HI" for the adaptive methods
  std::optional<double> drift_duration;  // default: the scene's duration; 0: no drift runs
  double stability_budget = 2e8;         // 0: the stable step is not measured by runs
  int points = 8, repeats = 1;
};

struct PreparedSweep {
  Prepared prepared;  // the scene and its settings, as `run` would take them
  SweepSettings settings;
};

// Checks the options (named as the command line's flags), loads the scene and sets the sweep
// up. Throws InputError.
PreparedSweep prepare_sweep(const std::string& scene, const SimOptions& sim,
                            const SweepOptions& options);

}  // namespace springlab::app
