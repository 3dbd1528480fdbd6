// The integration methods: one table that the command line, the app, the charts and the tests
// all read. Each entry gives a method's name, order, cost and stability, and its step function.
//
// Every step function advances a state by exactly h (adaptive methods take as many internal
// steps as their tolerance needs to get there), reading `in` and writing `out`, and counts its
// work in the workspace. docs/numerics.md ("Integrators") gives each update; the files in
// src/methods/ implement them, one method a file.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "springlab/butcher.hpp"
#include "springlab/energy.hpp"
#include "springlab/forces.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"
#include "springlab/tableau.hpp"

namespace springlab {

/// The methods, in the table's order; a row made from a tableau at run time has an id past these.
enum class Method {
  Euler,
  SymplecticEuler,
  Midpoint,
  ModifiedEuler,
  RK4,
  AdaptiveEuler,
  RK45,
  ImplicitEuler,
  Verlet,
  XPBD,
  LocalGlobal,
  VBD,
};

/// Settings of the methods that have any; plain values with defaults.
struct StepSettings {
  /// adaptive-euler: largest accepted |x_T - x_T/2| per internal step (m).
  /// rk45: the absolute and relative tolerance on each coordinate of x and v.
  double tolerance = 1e-4;
  /// The smallest internal step an adaptive method may take, as a fraction of h; below it the
  /// step fails (a diverging or too demanding run must not loop forever).
  double min_step_fraction = 1e-6;
  /// implicit-euler: conjugate gradients stop when |r| <= solver_tolerance |b|. The step is a
  /// first-order, once-linearised approximation; at 1e-5 the solve changes cloth positions by
  /// 1e-4 of the method's own error (implicit_euler.cpp). A diagonally implicit tableau's stages
  /// solve to the smaller of this and 1e-10 (tableau_steps.cpp: higher orders reach 1e-5's floor).
  double solver_tolerance = 1e-5;
  /// implicit-euler: the most conjugate-gradient iterations a solve may take; 0: six times the
  /// particles (reached only when the system is ill-posed). The solver-error study sets it.
  int max_solver_iterations = 0;
  /// xpbd, local-global, vbd: iterations a step (xpbd: Gauss-Seidel passes over the springs, one
  /// a sub-step in the small-steps form); 0: the row's own default
  /// (MethodInfo::default_iterations).
  int iterations = 0;
  /// local-global: Chebyshev acceleration (Wang 2015) with this estimate of the plain
  /// iteration's spectral radius, in [0, 1); 0: off.
  double chebyshev_rho = 0.0;
};

/// Work done, summed over steps. The machine-independent cost of a run.
struct Counters {
  std::int64_t force_evals = 0;         ///< evaluations of f(x, v) over all particles
  std::int64_t linear_solves = 0;       ///< implicit-euler: one per step
  std::int64_t solver_iterations = 0;   ///< conjugate-gradient iterations
  std::int64_t unconverged_solves = 0;  ///< solves stopped by the iteration cap
  std::int64_t newton_corrections =
      0;                          ///< a diagonally implicit tableau's stages: Newton's corrections
  std::int64_t halved_steps = 0;  ///< its steps taken as two halves, their stages not solved whole
  std::int64_t accepted = 0;      ///< internal steps kept (h-steps for fixed-step methods)
  std::int64_t rejected = 0;      ///< adaptive tries thrown away
};

struct ImplicitSolver;    // implicit_euler.cpp
struct IterativeSolvers;  // methods/iterative.hpp: xpbd, local-global, vbd
struct StageSolvers;      // methods/tableau_steps.hpp: a diagonally implicit tableau's stages
struct StepScratch;       // methods/step_scratch.hpp: the steps' stages, trials and blocks

/// Scratch memory and the little history some methods keep between steps. Allocated on first
/// use and reused, so a step allocates nothing once running. What only the steps use is behind
/// `scratch`; what the rest of the library reads is here.
struct Workspace {
  Workspace();
  ~Workspace();
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;

  Counters counters;
  SpringForces spring_forces;

  /// Verlet: the previous positions and a(x) at the current positions, valid while `verlet_ready`.
  Points x_prev, a_now;
  bool verlet_ready = false;
  double verlet_h = 0.0;

  /// Adaptive methods: the internal step to try next (0: start from h).
  double adaptive_step = 0.0;

  std::unique_ptr<ImplicitSolver> implicit;
  std::unique_ptr<IterativeSolvers> iterative;
  std::unique_ptr<StageSolvers> stages;
  /// The steps' own scratch: Runge-Kutta stages, adaptive trials, rk45's first-same-as-last
  /// derivative and the fused steps' per-block sums; null until a step needs it.
  std::unique_ptr<StepScratch> scratch;

  /// The check of the state a step made (energy.hpp), when the step made it itself: the explicit
  /// methods probe each block of particles as they finish it, while it is in cache, and sum the
  /// blocks in order (the same bits for any thread count). Cleared by step() before each step.
  std::optional<StepProbe> step_probe;

  /// Asked for (measure_power), the explicit methods measure in their force pass the power that
  /// damping and drag take out at the state they start from (dissipation_power(), energy.hpp), by
  /// blocks, summed in order. Cleared by step() before each step.
  bool measure_power = false;
  std::optional<double> input_power;

  /// The state or the model was changed from outside (contact, a drag, a parameter): forget what
  /// was derived from the last step (Verlet's history, rk45's first-same-as-last derivative).
  /// Counters and the adaptive step size are kept.
  void invalidate();
};

using StepFunction = void (*)(const Model& model, const State& in, State& out, double h,
                              const StepSettings& settings, Workspace& ws);
/// The step of a row made from a tableau (add_tableau_method): the same, given the row's tableau.
using TableauStepFunction = void (*)(const Tableau& tableau, const Model& model, const State& in,
                                     State& out, double h, const StepSettings& settings,
                                     Workspace& ws);

/// A step that cannot be completed (an adaptive step below its floor). The simulation reports it
/// as a divergence.
struct StepFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// A step whose method's own equations were not solved (a diagonally implicit tableau's stage
/// that Newton's iteration did not bring to its tolerance): the method is not unstable, and the
/// run says so ("its equations were not solved"), never "diverged".
struct SolveFailure : StepFailure {
  using StepFailure::StepFailure;
};

/// How a method steps, which decides how its stability is found, drawn and watched.
enum class MethodFamily {
  RungeKutta,   ///< explicit Runge-Kutta: its tableau gives R(z); a mode is stable while |R(h
                ///< lambda)| <= 1
  Partitioned,  ///< x and v in turn (no R(z)): a closed form per damped mode, the oscillator plane
  Implicit,     ///< solves for the new state: A-stable, |R(z)| <= 1 on the whole left half plane
  Adaptive,     ///< chooses its own steps: no fixed-step limit
  /// Solves the backward-Euler step approximately, by a fixed number of iterations (XPBD,
  /// local-global, vertex block descent): bounded at any step, with no R(z) of its own; what a
  /// large step costs is artificial damping and stretch, not stability.
  Iterative,
};

/// A method's own parameters, for the rows that read any (Verlet's damping factor d): what the
/// closed forms, the definite forms and the measured steps take beside the mode. A scene gives
/// them (method_parameters); the defaults are a method without its parameters' effect (d = 0).
struct MethodParameters {
  double verlet_damping = 0.0;  ///< position Verlet's damping factor d (Model::verlet_damping)
};
/// The parameters a scene's model gives its methods.
inline MethodParameters method_parameters(const Model& model) {
  return {.verlet_damping = model.verlet_damping};
}

/// The largest stable h on one damped mode x'' = -kappa x - gamma x', in closed form.
using ModeLimit = double (*)(double gamma, double kappa, const MethodParameters& parameters);

/// A partitioned method whose modes are stable exactly while a h^2 kappa + b h gamma <= c: the
/// scene's limit is where a h^2 K^ + b h C^ first reaches c I (stability.cpp, definite_limit).
struct DefiniteForm {
  double a, b, c;
};
using DefiniteRule = DefiniteForm (*)(const MethodParameters& parameters);

/// What a method keeps of a constant of the motion on a free body (momentum.hpp): to rounding
/// (exactly, as the update adds forces linearly or keeps x x v), only to its solver's tolerance
/// (the constant holds for the exact solution of its equations, which the solver approaches), or
/// not at all.
enum class Kept { Exactly, ToSolverTolerance, No };
/// "kept", "kept to the solver's tolerance", "not kept".
const char* kept_text(Kept kept);
struct MethodInfo;
/// What a row keeps, as docs/methods.md's table writes it: "P", "P, L", "P to the solver's
/// tolerance", "neither".
std::string kept_summary(const MethodInfo& method);

/// A row of the method table: everything a method says of itself. Its name, order, cost,
/// family, what its stability needs (its tableau's R(z), a closed form, a definite form), its
/// step function and its defaults (how it is shown, its colour and mark, is the app's:
/// app/draw/row_styles.cpp). The app, the command line, the charts, the
/// stability analysis, the studies and the tests all read these rows (methods()) and branch on
/// what a row says, never on which row it is: adding a method is its row and its step
/// (tests/app/new_row_test.cpp adds one and runs it through every consumer).
struct MethodInfo {
  Method id;
  const char* name;         ///< as typed on the command line
  const char* label;        ///< as shown to people
  int order;                ///< global order of accuracy in positions
  const char* evaluations;  ///< force evaluations per step, as a sentence fragment
  /// Largest stable h * w on the undamped oscillator x'' = -w^2 x: 0 = never stable,
  /// infinity = always, NaN = not a fixed-step method (the step size is controlled).
  double undamped_limit;
  const char* stability;  ///< one line: why, for the stability gauge
  MethodFamily family;
  StepFunction step = nullptr;  ///< nullptr: the row steps with tableau_step
  /// Runge-Kutta and implicit rows: the tableau (R(z) in tableau.hpp, the region chart's edge).
  const Tableau* tableau = nullptr;
  /// Rows made from a tableau at run time step with this instead of `step`.
  TableauStepFunction tableau_step = nullptr;
  /// The mode's limit in closed form where there is one (every partitioned row; for a
  /// Runge-Kutta row a shortcut the contract test holds to R(z)); otherwise from R(z).
  ModeLimit mode_limit = nullptr;
  /// Partitioned rows: the definite form, if the limit is one; otherwise the least over the
  /// scene's numerical range (how the analysis searches it is its own business:
  /// core/src/stability/analysis_rows.hpp).
  DefiniteRule definite = nullptr;
  /// The energy audit watches it (simulation.cpp, audited()): not where the divergence test
  /// sees instability at once (symplectic Euler, Verlet) nor the adaptive ones.
  bool audited = false;
  /// What it keeps on a free body: the momentum P and the angular momentum L (momentum.hpp),
  /// measured by tests/core/momentum_test.cpp. Every row that adds forces linearly keeps P; L
  /// only a symplectic update (symplectic Euler, Verlet, a tableau with b_i a_ij + b_j a_ji =
  /// b_i b_j, Cooper 1987). VBD keeps neither unless its iterations converge.
  Kept momentum = Kept::Exactly;
  Kept angular_momentum = Kept::No;

  /// Iterative rows: iterations a step when the settings leave it at 0 (StepSettings::iterations),
  /// and what one iteration is, as the run's account writes it ("passes over the springs").
  int default_iterations = 0;
  const char* iteration_unit = nullptr;
  /// Reads StepSettings::chebyshev_rho (local-global's acceleration; warned past its radius).
  bool reads_rho = false;
  /// Its step carries a history in the workspace besides (x, v): the previous positions and
  /// a(x) (Verlet's x_prev and a_now). The measured limit steps that three-part state, and its
  /// transient growth has no energy norm of (x, v) to be measured in.
  bool history = false;
  /// One of the rows the app compares when neither the scene nor the user chose any.
  bool compared_first = false;

  bool adaptive() const { return family == MethodFamily::Adaptive; }
  bool implicit() const { return family == MethodFamily::Implicit; }
  /// Stable at any step: no limit to find, no sub-steps to choose.
  bool any_step() const {
    return family == MethodFamily::Implicit || family == MethodFamily::Iterative;
  }
  /// Never stable without damping, so damping can buy a limit.
  bool damping_helps() const { return undamped_limit == 0.0; }
};

std::span<const MethodInfo> methods();
/// The rows compiled in (the first of methods()), and the rows added since (add_method,
/// add_tableau_method): a user's own are listed apart from the built-in ones.
std::span<const MethodInfo> built_in_methods();
std::span<const MethodInfo> added_methods();
const MethodInfo& method_info(Method method);
std::optional<Method> find_method(std::string_view name);

/// Adds a row with a step function of its own (`step` set, `tableau_step` not), after the
/// built-in rows and the rows made so far, for the rest of the process: a method written
/// outside the library (a test's, a student's) is then stepped, analysed, compared and drawn as
/// a built-in one is. Its id is given here (row.id is ignored) and its strings are copied. The
/// same name twice, a row without a step, or more than 32 added rows throw InputError.
Method add_method(const MethodInfo& row);
/// A row made from a tableau read as data (springlab/butcher.hpp), added to the table for the rest
/// of the process, after the built-in rows: explicit tableaux step as RK4 does, diagonally
/// implicit ones solve each stage as an implicit Euler step (tableau_steps.cpp); the stability
/// analysis, the sub-steps, the gauge, the audit and the region chart read its R(z) as they read
/// RK4's. Its id is a Method past the enum's values. The same name and entries again give the
/// same row; the same name with other entries, a built-in's name, or more than 32 added rows
/// throw InputError. Rows are never removed (threads may be reading them).
Method add_tableau_method(const ButcherTableau& tableau, const std::string& name);
/// The tableau a row was made from (add_tableau_method); nullptr for a built-in row.
const ButcherTableau* tableau_source(Method method);
/// "euler, symplectic-euler, ..., vbd": the built-in rows, for messages (a user's own rows apart).
std::string method_names();

/// Advances `in` by h into `out` (which must not be `in`) with the method, counting the work.
void step(Method method, const Model& model, const State& in, State& out, double h,
          const StepSettings& settings, Workspace& ws);

/// The iterations an iterative row (xpbd, local-global, vbd) takes a step: the setting, or the
/// row's own default (default_iterations: xpbd 1 pass, the others 10).
int iterations_for(Method method, const StepSettings& settings);

/// One evaluation of the accelerations, counted.
void accelerations(const Model& model, const Points& x, const Points& v, Points& a, Workspace& ws);

}  // namespace springlab
