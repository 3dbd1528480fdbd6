// How large a step a scene takes before a method blows up: the one place that says so, for the
// gauge, the warnings, the divergence messages, `run`'s summary, `compare` and the automatic
// sub-steps.
//
// A scene is linearised at its equilibrium (the static balance it settles into, with its pins,
// a held particle and gravity: a hanging rope in tension), pinned particles removed:
//   M x'' + C x' + K x = 0,  K = -df/dx (definite spring Jacobians), C = -df/dv (spring damping
//   along each spring, and the drag).
// In mass-scaled coordinates K^ = M^-1/2 K M^-1/2 and C^ are symmetric positive semidefinite, and
// every eigenvalue lambda of the first-order system, with its eigenvector x (|x| = 1), solves the
// scalar equation of one damped mode
//   lambda^2 + gamma lambda + kappa = 0,   gamma = x^* C^ x,  kappa = x^* K^ x,
// so each eigenvalue is a mode (kappa = w^2, gamma = c) whose stability mode_limit() gives in
// closed form. Then, per method:
//
//   euler, midpoint, rk4      Runge-Kutta methods, stable while |R(h lambda)| <= 1 for every
//                             lambda. Small scenes: every eigenvalue, exactly (a dense solve).
//   modified-euler            The same with C^ + (h/2) K^ as damping (its step is explicit Euler
//                             on that system). Large scenes, and modified Euler: every (gamma,
//                             kappa) of an eigenvector lies in the joint numerical range W of
//                             (C^, K^), a convex set whose boundary is traced by the top
//                             eigenvectors of cos(phi) K^ + sin(phi) C^ (Lanczos); the least
//                             mode_limit() over W bounds the limit from below, and it is the
//                             limit exactly when the vector that attains it is an eigenvector
//                             (checked by its residual). So a limit is exact, or "at least".
//   symplectic-euler, verlet  Their roots leave the unit disc only through -1 (a complex pair
//                             has |mu|^2 = 1 - h gamma for one mode; the same holds for the
//                             matrix step, as x^* Q(mu) x = 0 shows), so the limit is exactly
//                             the largest h with  a h^2 K^ + b h C^ <= c I  (positive
//                             semidefinite): (1, 2, 4) for symplectic Euler and
//                             (1, 4 - d, 4 - 2 d) for Verlet with its damping d. Found by
//                             Newton's method on the largest eigenvalue (Lanczos), at any size.
//
// The limiting mode (its frequency, damping ratio and shape) comes with each limit.
#pragma once

#include <atomic>
#include <complex>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

// ---- One damped mode, x'' = -kappa x - gamma x' ------------------------------------------------

/// The largest h such that every step up to it keeps the method's spectral radius at most 1:
/// 0 = unstable at any step, infinity = at any step, NaN = the method chooses its own steps.
double mode_limit(Method method, double gamma, double kappa,
                  const MethodParameters& parameters = {});
/// The same as a function of w = sqrt(kappa) and c = gamma.
double stable_step(Method method, double w, double c, const MethodParameters& parameters = {});
/// The first h > 0 with |R(h lambda)| > 1, for euler, midpoint and rk4 (NaN for the others).
double runge_kutta_limit(Method method, std::complex<double> lambda);
/// Spectral radius of one step of size h on x'' = -w^2 x - c x', from the method's own step
/// function applied to that oscillator as it runs (Verlet with the history it keeps): what the
/// closed forms are checked against.
double amplification(Method method, double w, double c, double h,
                     const MethodParameters& parameters = {});
/// The most a stable step can raise the mode's energy, over any number of steps: sup over n of
/// |S^n|^2 in the energy norm (kappa x^2 + v^2) / 2, S that step as a matrix. 1 for a normal
/// contraction; above 1 where S is far from normal (near critical damping, near a limit);
/// infinity where the mode grows (and for Verlet, whose state holds a history).
double transient_growth(Method method, double gamma, double kappa, double h,
                        const MethodParameters& parameters = {});

// ---- The equilibrium ----------------------------------------------------------------------------

/// The static balance of the scene as it is now: positions where the springs and gravity are in
/// balance (colliders, drag and fields play no part), velocities zero. Gravity acts on the
/// particles joined by springs to a pinned one; a part with nothing pinned only relaxes its
/// springs (it would fall forever). Within budgets (equilibrium.cpp), its largest force is below
/// 1e-8 of the larger of its springs' force at 1 % strain and its heaviest held particle's
/// weight, where a factorisation of its stiffness is cheap (a rope, a small scene: Newton's
/// method), else (a cloth from 26 x 26) 4e-2 of that weight or of that spring force, the less,
/// and 1e-5 of the spring force where there is no weight (relaxation alone).
State equilibrium(const Model& model, const State& state);
/// A lower bound on the total energy of the scene whose equilibrium is `rest` (above:
/// StabilityAnalysis::lowest_energy()).
double lowest_energy(const Model& model, const State& rest);

// ---- A scene's limits ---------------------------------------------------------------------------

/// The mode that sets a method's limit: one damped mode of the linearised scene.
struct LimitingMode {
  double w = 0.0;                ///< rad/s
  double c = 0.0;                ///< 1/s, the damping rate: the mode decays as e^(-c t / 2)
  double damping_ratio() const;  ///< c / (2 w)
  Points shape;  ///< each particle's displacement in the mode, the largest of length 1
};

/// A method's largest stable step on a scene, exact or a lower bound, and the mode that sets it.
struct StabilityLimit {
  Method method = Method::Euler;
  /// The largest stable step (s): 0 = unstable at any step, infinity = stable at any step,
  /// NaN = the method chooses its own steps.
  double h = 0.0;
  bool exact = true;  ///< else h is a lower bound: stable at least up to h
  std::optional<LimitingMode> mode;
  double residual = 0.0;  ///< of the limiting mode as an eigenvector (0: computed as one)
};

/// "stable up to h = 0.0283 s", "stable at least up to h = ...", "unstable at any step (not
/// enough damping)", "stable at any step", "the method chooses its own step sizes".
std::string describe(const StabilityLimit& limit);

/// Free coordinates up to which every eigenvalue is computed (a dense eigen-solver on twice as
/// many: 0.2 s here at 240).
inline constexpr int kDenseDofs = 240;

/// A scene's stability, computed once (the expensive part: the equilibrium, the eigenvalues)
/// for every method; immutable, so it may be computed on one thread and read on another.
/// limit() gives each method's largest stable step, exact or a lower bound, with its limiting
/// mode (frequency, damping ratio, shape).
class StabilityAnalysis {
 public:
  /// `dense_dofs`: up to how many free coordinates every eigenvalue is computed (the tests make
  /// the large scenes' path run on small ones, to check it against the dense one). `cancel`, when
  /// set while it runs (from another thread), stops it within milliseconds (a factorisation
  /// under way is finished first): it is then cancelled() and says nothing. Its searches run
  /// side by side on up to thread_count() threads (forces.hpp), with the same results on any.
  StabilityAnalysis(const Model& model, const State& state, int dense_dofs = kDenseDofs,
                    const std::atomic<bool>* cancel = nullptr);
  bool cancelled() const { return cancelled_; }

  /// Whether the scene has oscillating modes (springs with stiffness on free particles); if not,
  /// why ("no springs", "every particle is pinned"), and the limits come from the drag alone.
  bool oscillates() const { return oscillates_; }
  const std::string& no_modes_reason() const { return no_modes_; }
  double w_max() const { return w_max_; }      // rad/s, the highest frequency (undamped)
  double w_bound() const { return w_bound_; }  // rad/s, Gershgorin's bound on it
  bool dense() const { return dense_; }        // every eigenvalue computed
  int dofs() const { return dofs_; }           // free coordinates
  double seconds() const { return seconds_; }  // what the analysis took, wall time

  const StabilityLimit& limit(Method method) const;

  /// What the energy audit (energy_audit.hpp) allows a stable run: over the scene's modes (dense
  /// scenes: every eigenpair; large ones: the traced boundary of W), the largest transient growth
  /// of those the method at step h keeps stable, and how many it does not.
  struct Growth {
    double factor = 1.0;
    int growing = 0;
  };
  Growth transient_growth(Method method, double h, const MethodParameters& parameters = {}) const;
  /// A lower bound on the scene's total energy: the equilibrium's for the parts held by a pin (the
  /// least potential near it), springs at rest and each particle on the lowest floor for the parts
  /// that are not; -infinity when nothing bounds it (a part that can fall forever, a field).
  double lowest_energy() const { return lowest_energy_; }
  /// The RMS stretch of the springs at the equilibrium (iterative_cost.hpp): what an iterative
  /// method's settled stretch is measured against.
  double rest_stretch() const { return rest_stretch_; }

  /// For the stability-region chart. The eigenvalues of the first-order system (dense scenes:
  /// all of them; large ones: none). The modes as (gamma, kappa) points: dense scenes, one per
  /// eigenvalue (gamma = -2 Re lambda, kappa = |lambda|^2 for a complex pair; a real pair as
  /// one point); large scenes, the traced boundary of W, within which every mode lies.
  struct ModePoint {
    double gamma = 0.0, kappa = 0.0;
  };
  const std::vector<std::complex<double>>& eigenvalues() const { return eigenvalues_; }
  const std::vector<ModePoint>& modes() const { return modes_; }

 private:
  bool oscillates_ = false, dense_ = false, cancelled_ = false;
  void analyse(const Model& model, const State& state, int dense_dofs);
  std::string no_modes_;
  double w_max_ = 0.0, w_bound_ = 0.0, seconds_ = 0.0;
  int dofs_ = 0;
  std::vector<StabilityLimit> limits_;  // one per method, in table order
  // Rows made from tableaux after the analysis (the app's "Run beside"): their limits from the
  // modes found, made when first asked for. Shared, so that the analysis stays copyable.
  struct Late {
    std::mutex mutex;
    std::deque<StabilityLimit> limits;
  };
  std::shared_ptr<Late> late_ = std::make_shared<Late>();
  std::vector<std::complex<double>> eigenvalues_;
  std::vector<ModePoint> modes_;
  std::vector<ModePoint> growth_modes_;  // (gamma, kappa) of each mode, real eigenvalues included
  double lowest_energy_ = -std::numeric_limits<double>::infinity();
  double rest_stretch_ = 0.0;
};

// ---- A quick bound, while the analysis runs
// -------------------------------------------------------

/// A step every mode of the scene as it is takes stably, from bounds that cost one pass over the
/// springs (no equilibrium, no eigenvalues: milliseconds on a 128 x 128 cloth). Every mode's
/// (gamma, kappa) lies in the rectangle [gamma_lo, gamma_hi] x [0, kappa_hi]: kappa_hi and gamma_hi
/// Gershgorin's bounds on K^ and C^ at this state, gamma_lo the drag's least rate k_drag / m. The
/// limit is the least over that rectangle: at its corners for the methods whose mode limit is
/// monotone along each edge (euler, modified-euler, symplectic-euler, verlet: proven), and for
/// midpoint and rk4 the least over a grid of it, less a tenth. Never above the analysis' limit;
/// often well below it (the rectangle holds more than the modes). 0 where it cannot tell (no
/// drag, for the methods that need damping).
StabilityLimit quick_limit(Method method, const Model& model, const State& state);

// ---- Automatic sub-steps ------------------------------------------------------------------------

/// The fraction of a method's stated limit the automatic sub-steps keep h within, unless a scene
/// says otherwise ("safety": a scene made to show a divergence gives one above 1). A half: the
/// limit is that of small motions about the equilibrium, and a rope that whips or a cloth that
/// swings stretches its springs beyond their hanging tension (the fastest sideways modes of a
/// swinging rope run up to twice as fast as at rest).
inline constexpr double kSafeFraction = 0.5;
/// The most sub-steps the automatic choice takes (a stiff chain under explicit Euler would want
/// millions a frame); reaching it is said.
inline constexpr int kMaxAutoSubsteps = 10000;

struct SubstepChoice {
  int substeps = 1;
  /// The limit wanted more than the cap, or is 0 (unstable at any step: then no number of
  /// sub-steps helps, and the choice is 1).
  bool capped = false;
};
/// The fewest sub-steps n with dt / n <= fraction * limit.h (1 when the method is stable at any
/// step or chooses its own steps).
SubstepChoice choose_substeps(const StabilityLimit& limit, double dt, double fraction,
                              int cap = kMaxAutoSubsteps);

// ---- Measured by runs ---------------------------------------------------------------------------

/// The largest step at which the method's own runs hold, found by bisection on h: each run starts
/// at the scene's equilibrium (colliders and fields left out) with a tiny random push (the linear
/// regime) and counts as unstable when its energy grows a thousandfold. A run is as long as the
/// mode `expected` names needs to grow 1e9-fold just past the bracket, within a budget of work
/// (particle- and spring-steps; 2e8 is about a second here), a probe at most a twentieth of it;
/// the bracket stops narrowing where runs would have to be longer or the budget is spent, and
/// `resolution` says how far it got. 0 = unstable from h w = 0.3 (or guess / 1000) down,
/// infinity = stable past 1000 guess, NaN for the adaptive methods. The budget holds for the
/// probes upwards too: where it runs out while every step probed held (a method stable at any
/// step, on a large scene), h is the largest step probed and `at_least` says so.
struct MeasuredLimit {
  double h = 0.0;
  /// Relative: the bracket's width, or how far past a limit growth is too slow for the runs to
  /// see, whichever is larger. The true limit is within it of h (infinite with `at_least`).
  double resolution = 0.0;
  /// Every probe held up to h, and the budget was spent: stable at least to h, not probed past.
  bool at_least = false;
};
/// `w_max` sets the scale when the expected limit has no mode (0 or infinity).
MeasuredLimit measured_limit(Method method, const Model& model, const State& state,
                             const StabilityLimit& expected, double w_max,
                             const StepSettings& settings = {}, double budget = 2e8);

}  // namespace springlab
