// The simulation options every command shares (docs/command-line.md, "Options") as command-line
// flags; what they mean and how they are checked is options/scene_options.hpp.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "options/scene_options.hpp"
#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"

namespace springlab::app {

// Adds --method --dt --substeps --ks --kd --tol --set --threads, and with `with_length`
// --steps and --duration.
void add_sim_options(CLI::App& command, SimOptions& options, bool with_length = true);

// A warning on stderr when the step is past the method's estimated stability limit (the run
// will most likely diverge), with the step that would do.
void warn_if_unstable(Simulation& sim, const std::string& scene);

// --compare-layout, in `view` and `render`.
inline constexpr const char* kCompareLayoutHelp =
    "how compare shows its lanes: apart (a view each, the default: lanes that agree cannot hide "
    "one another) or "
    "together (one view, each lane in its colour)";

// For an integer option: accepts a whole number written any way ("1e6"), refuses anything else
// with the range: "--steps: must be a whole number in [1, 1e+12], got 2.5".
CLI::Validator whole_number(double lo, double hi);

}  // namespace springlab::app
