// How large a step a scene takes before a method blows up.
//
// The scene's highest natural frequency w_max is the square root of the largest eigenvalue of
// M^-1 K (K = -df/dx, the stiffness matrix at the current positions), found by Lanczos iteration
// on the symmetric M^-1/2 K M^-1/2; Gershgorin's bound w_max^2 <= max_i (2 / m_i) sum k_s
// brackets it from above. The damping of that mode, c = (q^T C q) / (q^T M q) with C = -df/dv,
// matters too: explicit Euler is stable exactly while h <= c / w^2.
//
// A method's limit comes from its own step function, applied to the oscillator
// x'' = -w^2 x - c x' (a particle on a spring to a pinned anchor): one step is a linear map of
// (x, v), and the method is stable while that map's spectral radius is at most 1. The largest
// stable step is found by scanning h w upwards and bisecting at the first instability, so the
// limits in NUMERICS.md (2/w, 2 sqrt(2)/w, k_d/k_s...) are computed, not copied.
#pragma once

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct StabilityEstimate {
  double w_max = 0.0;    // rad/s, Lanczos (a lower bound that converges up to it)
  double w_bound = 0.0;  // rad/s, Gershgorin upper bound
  double damping = 0.0;  // 1/s, c of the highest mode: spring_damping + drag_damping
  double spring_damping = 0.0, drag_damping = 0.0;  // its parts, in proportion to k_d and k_drag
  int iterations = 0;      // Lanczos steps
  bool converged = false;  // else stopped at the cap on work, for a very large scene

  // The same estimate after every k_s, every k_d or the drag was multiplied by `factor` (the
  // mode is unchanged: K and C scale): w_max and w_bound by sqrt(factor), the damping part.
  void scale_stiffness(double factor);
  void scale_spring_damping(double factor);
  void scale_drag(double factor);
};

StabilityEstimate estimate_stability(const Model& model, const State& state);

// h w below which "unstable at any step" is decided: see stability.cpp.
inline constexpr double kNeverStableFrom = 0.05;
inline constexpr double kNeverStableFromByRuns = 0.3;

// Spectral radius of one step of size h on x'' = -w^2 x - c x'.
double amplification(Method method, double w, double c, double h, double verlet_damping = 0.0);

// The largest h for which every step size up to it is stable on that oscillator:
// 0 = unstable at any step (from h w = kNeverStableFrom up), infinity = stable at any step, NaN = the method
// chooses its own steps.
double stable_step(Method method, double w, double c, double verlet_damping = 0.0);

// Linear stability belongs to an equilibrium, where a step's stages do not move and the
// linearised step is exactly the method's step matrix: the scene without colliders, relaxed to
// its static balance of springs and gravity (gravity dropped when nothing is pinned, since it
// would only fall), at rest. A held cloth or rope then hangs in tension, which leaves only rigid
// motions without stiffness.
struct EquilibriumScene {
  Model model;
  State state;
};
EquilibriumScene at_rest(const Model& model, const State& state);

// Measured on the scene itself, with the method's own step: the spectral radius of the step map
// y -> step(y) linearised at `state` (free particles only), from its whole finite-difference
// Jacobian and exact eigenvalues; NaN past kDenseDofs free coordinates. The neutral modes of a
// scene at rest (eigenvalue 1, zero stiffness) are left out: see outermost() in stability.cpp.
inline constexpr int kDenseDofs = 300;
double measured_amplification(Method method, const Model& model, const State& state, double h,
                              const StepSettings& settings = {});



// The largest h at which the spectral radius at that equilibrium stays at most 1 (to 1e-9 dense,
// 1e-3 by Arnoldi), found by bracketing from `guess` and bisecting: 0 = unstable from 0.01 / w_max up,
// infinity = stable past 1e6 / w_max (100 for the runs), NaN for the adaptive methods.
double measured_stable_step(Method method, const Model& model, const State& state, double w_max,
                            double guess, const StepSettings& settings = {});
// The same from an equilibrium already found (at_rest), to measure several methods.
double measured_stable_step(Method method, const EquilibriumScene& rest, double w_max, double guess,
                            const StepSettings& settings = {});

}  // namespace springlab
