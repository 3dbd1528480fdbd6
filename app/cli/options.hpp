// The simulation options every command shares (DESIGN.md, "The command line"), and turning a
// scene argument plus those options into a ready Simulation.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"

namespace springlab::app {

struct SimOptions {
  std::optional<std::string> method;
  std::optional<double> dt;
  std::optional<std::string> substeps;  // a whole number, or "auto"
  std::optional<std::int64_t> steps;
  std::optional<double> duration;
  std::optional<double> ks, kd, tol;
  std::vector<std::string> sets;
  std::optional<int> threads;
};

// Adds --method --dt --substeps --ks --kd --tol --set --threads, and with `with_length`
// --steps and --duration.
void add_sim_options(CLI::App& command, SimOptions& options, bool with_length = true);

struct Prepared {
  Scene scene;
  SimulationSettings settings;
  std::int64_t steps = 0;  // from --steps, or --duration (or the scene's) / dt
};

// Loads the scene (name or path), applies --set, --ks, --kd, --method, --dt, --substeps, --tol
// and --threads, and checks every value. Throws InputError.
Prepared prepare(const std::string& scene, const SimOptions& options);

// `compare` and `bench` time integrators: an inverse-kinematics scene has none to time.
void require_integration(const Scene& scene, const char* command);

// A warning on stderr when the step is past the method's estimated stability limit (the run
// will most likely diverge), with the step that would do.
void warn_if_unstable(Simulation& sim, const std::string& scene);

// For an integer option: accepts a whole number written any way ("1e6"), refuses anything else
// with the range: "--steps: must be a whole number in [1, 1e+12], got 2.5".
CLI::Validator whole_number(double lo, double hi);

// Checks an option's value: "--dt: must be in (0, 1] s, got -1". Throws InputError.
void check_option(const char* name, double value, double lo, double hi, bool lo_open,
                  const char* unit = "");

}  // namespace springlab::app
