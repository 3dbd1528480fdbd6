// Accuracy against cost (docs/numerics.md, "Accuracy and cost"): every method run on one scene over
// a range of steps (adaptive methods: of tolerances), each run's error against a reference, its
// cost, the order fitted to its errors, its largest stable step measured and from theory, and
// the energy each method gains or loses over a long run. What `springlab compare` and the app's
// Compare panel chart.
//
// Steps are h = H / n for whole n (H the coarsest step), so every run passes through the common
// sample times k H, where errors are taken: the largest over the samples of the RMS over free
// particles of |x - x_ref|. The reference is the exact solution where the scene has one, else
// RK4 at a step 16 times smaller than the finest charted, itself checked against RK4 at twice
// its step (its own error is about a fifteenth of that difference).
#pragma once

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/solver_error.hpp"
#include "springlab/stability.hpp"
#include "springlab/state.hpp"

namespace springlab {

/// What a sweep runs: which methods, over which steps (and tolerances), for how long.
struct SweepSettings {
  std::vector<Method> methods;  ///< empty: every method
  double h_min = 1e-3, h_max = 1e-2;
  int points = 8;  ///< steps (and tolerances) per method, log-spaced
  double duration = 2.0;
  double tol_min = 1e-10, tol_max = 1e-4;  ///< for the adaptive methods
  int repeats = 1;                         ///< runs timed this many times; the fastest counts
  int workers = 0;                         ///< threads running runs at once; 0: every core
  StepSettings step;
  bool stability = true;  ///< measure each method's largest stable step
  double stability_budget =
      2e8;  ///< particle- and spring-steps per method for that (stability.hpp)
  /// The energy-drift runs: each method at this step for this long (0: no drift runs), with these
  /// sub-steps (automatic, as the app and `run` choose them, or fixed).
  double drift_h = 0.0, drift_duration = 0.0;
  int drift_substeps = 1;
  bool drift_auto_substeps = false;
  double drift_safety = kSafeFraction;
};

/// One run of a sweep: a method at one step (or tolerance), its error and its cost.
struct SweepRun {
  Method method = Method::Euler;
  double h = 0.0;  ///< the outer step: samples are every H / h of them
  /// Adaptive methods: the tolerance; NaN for a fixed-step run (an adaptive method then accepts
  /// every try: its order is measured that way, like everyone's).
  double tolerance = std::numeric_limits<double>::quiet_NaN();
  double mean_step = 0.0;  ///< duration / internal steps taken (h for fixed-step methods)
  double error = 0.0;      ///< m; infinity when the run diverged
  double seconds = 0.0;    ///< wall time of the fastest repeat
  Counters counters;
  bool diverged = false;
  double diverged_at = std::numeric_limits<double>::quiet_NaN();
  /// The energy audit (energy_audit.hpp), run without stopping the run: how far the net energy
  /// rose above an earlier low where no stable step lets it (J; 0 if it never did), and whether
  /// it did or the run diverged: numerically unstable.
  double rise = 0.0;
  bool unstable = false;
};

/// A method over a sweep: its fitted order and its stable step, measured and from the analysis.
struct MethodSummary {
  Method method = Method::Euler;
  double order = std::numeric_limits<double>::quiet_NaN();  ///< fitted; NaN: too few points
  int fitted_points = 0;
  /// Where the errors stop falling as the step shrinks (the last runs' errors no lower than the
  /// fitted runs' least): their level and the largest step at which it starts, both NaN where
  /// there is none. The order is fitted above it: below it the error is the solvers' tolerance
  /// and rounding, which a smaller step does not reduce.
  double floor_error = std::numeric_limits<double>::quiet_NaN();
  double floor_h = std::numeric_limits<double>::quiet_NaN();
  /// The largest stable step measured by runs (stability.hpp, measured_limit), to within
  /// measured_resolution (relative), and the analysis's (exact, or a lower bound).
  double measured_stable_h = std::numeric_limits<double>::quiet_NaN();
  double measured_resolution = 0.0;
  bool measured_at_least =
      false;  ///< the budget ran out with every probe held: stable at least to it
  double theoretical_stable_h = std::numeric_limits<double>::quiet_NaN();
  bool theory_exact = true;
};

/// A method's energy drift at the scene's own step, over time.
struct DriftTrace {
  Method method = Method::Euler;
  int substeps = 1;              ///< chosen, or as given
  std::vector<double> t, drift;  ///< drift = (E + dissipated - E0) / energy scale
  bool diverged = false;
};

/// Everything a sweep measured: its runs, each method's summary, the drift runs, the reference.
struct SweepResult {
  std::vector<SweepRun> runs;  ///< grouped by method in the order asked, steps from coarse to fine
  std::vector<MethodSummary> methods;
  std::vector<DriftTrace> drift;
  std::string reference;         ///< "exact solution" or "rk4 at h = ... s"
  double reference_error = 0.0;  ///< m, estimated
  /// The errors an order is fitted between: above the reference's error (100 times it) and
  /// round-off, below a tenth of the motion.
  double fit_floor = 0.0, fit_ceiling = 0.0;
  double sample_interval = 0.0;  ///< H
  int samples = 0;
  double motion = 0.0;  ///< m: the largest RMS displacement of the reference from the start
  double w_max = 0.0;   ///< rad/s, the highest frequency at the equilibrium
  /// The iterative methods' solver error at one step a frame (h = 1/60 s, or the coarsest step
  /// if larger), from the scene after the sweep's duration (empty curves: none was swept).
  SolverErrorStudy solver;
  bool cancelled = false;
};

/// Calls `on_run` (from the worker that finished it, one at a time) after each run, with the
/// number of jobs done and in all; stops early, marking the result cancelled, when `cancel` is
/// set. Results are the same whatever the number of workers (only the seconds differ).
SweepResult run_sweep(const Model& model, const State& initial, const SweepSettings& settings,
                      const std::function<void(const SweepRun&, int done, int total)>& on_run = {},
                      const std::atomic<bool>* cancel = nullptr);

/// The same sweep taken a piece at a time by its caller, for an app without threads (the
/// browser's runs pieces between its frames, the charts filling in as on the desktop): first the
/// reference, then its check, then the jobs' plan (the stability analysis), then one job a call.
/// The same jobs as run_sweep's, and the same result.
class SweepInSteps {
 public:
  SweepInSteps(const Model& model, const State& initial, const SweepSettings& settings);
  ~SweepInSteps();
  SweepInSteps(SweepInSteps&&) noexcept;
  SweepInSteps& operator=(SweepInSteps&&) noexcept;

  /// Does the next piece; calls `on_run` after a job as run_sweep does. False once all is done.
  bool step(const std::function<void(const SweepRun&, int done, int total)>& on_run = {});
  bool done() const;
  /// Jobs done and in all (0 of 0 until the plan is made).
  std::pair<int, int> progress() const;
  /// The runs so far; everything, the fitted orders too, once done.
  const SweepResult& result() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The slope of log(error) against log(step) over the fixed-step runs of one method that are
/// stable, well above the reference's error and round-off, and below a tenth of the motion
/// (where the error is still small enough to scale as a power of the step). NaN with fewer than 3
/// such runs. (Against the mean step of its tolerance runs, RK45 on the spring shows 6, not 5:
/// its controller spreads the steps unevenly over a period.)
double fitted_order(const std::vector<SweepRun>& runs, Method method, double floor, double ceiling,
                    int* points = nullptr);
/// The same, above the floor its own errors show: the runs from the finest back while each error
/// is no lower than half the least error of the coarser runs are the floor (at least two of them,
/// and never so many that fewer than three are left to fit); `summary` gets the order, the points
/// fitted and the floor's level and step.
void fit_order_above_floor(const std::vector<SweepRun>& runs, Method method, double floor,
                           double ceiling, MethodSummary& summary);

/// The n of the steps H / n: `count` whole numbers from 1 to about H / h_min, log-spaced,
/// distinct.
std::vector<int> step_divisors(double h_min, double h_max, int count);

}  // namespace springlab
