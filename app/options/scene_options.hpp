// The scene to open and the options that set it up (method, dt, sub-steps, k_s, k_d, ...), and
// turning them into a ready scene and settings with every value checked. Platform-neutral: the
// command line fills SimOptions from its flags, the browser from the page's link; both get the
// same checks and the same messages ("--dt: must be in (0, 1] s, got -1").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "springlab/methods.hpp"
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
  std::optional<int> iterations;  // xpbd, local-global, vbd
  std::optional<double> rho;      // local-global's Chebyshev acceleration
  std::vector<std::string> sets;
  std::optional<int> threads;
};

struct Prepared {
  Scene scene;
  SimulationSettings settings;
  std::int64_t steps = 0;  // from --steps, or --duration (or the scene's) / dt
};

// Loads the scene (name or path), applies --set, --ks, --kd, --method, --dt, --substeps, --tol
// and --threads, and checks every value. Throws InputError.
Prepared prepare(const std::string& scene, const SimOptions& options);

// A method as --method names it (lookup_method: a built-in row, a shipped tableau or a tableau
// file), or InputError: "--method: unknown method 'rk5'; did you mean 'rk4'? (methods: ...)".
Method resolve_method(const std::string& name);

// `compare` and `bench` time integrators: an inverse-kinematics scene has none to time.
void require_integration(const Scene& scene, const char* command);

// Checks an option's value: "--dt: must be in (0, 1] s, got -1". Throws InputError.
void check_option(const char* name, double value, double lo, double hi, bool lo_open,
                  const char* unit = "");

// A whole number written any way ("1e6") within [lo, hi], as its plain digits in `text`; or the
// reason it is not: "must be a whole number in [1, 1e+12], got 2.5" (text left as it was).
std::string parse_whole_number(std::string& text, double lo, double hi);

// Methods from "euler,heun,mine.json": built-in methods, shipped tableaux or tableau files
// (lookup_method, util/data_dir.hpp). Throws InputError naming `option`.
std::vector<Method> parse_method_list(const std::string& text, const char* option);

}  // namespace springlab::app
