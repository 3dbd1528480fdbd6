// Momentum: what springs alone never change. A spring pulls its two ends equally and oppositely
// (Newton's third law) along the line between them (a central force), so on a free body, where
// no outside force acts, the momentum and the angular momentum
//   P = sum m v,   L = sum m x x v   (about the origin, over the free particles)
// are constants of the motion. A method keeps P exactly when its update adds up forces linearly
// (every Runge-Kutta method, symplectic Euler, a converged implicit step); it keeps L only if it
// also keeps the quadratic invariant x x v (symplectic Euler, Verlet, XPBD's projections do).
// The method table says which each keeps, measured (tests/core/momentum_test.cpp).
#pragma once

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

/// No outside force acts: nothing pinned, no gravity, drag, attractor, emitter or collider.
/// Only there is momentum a constant of the motion, and its change the method's.
bool free_body(const Model& model);

struct Momentum {
  Vec3 linear = Vec3::Zero();   ///< P, kg m/s
  Vec3 angular = Vec3::Zero();  ///< L about the origin, kg m^2/s
  /// What a change is measured against: sum m |v| and sum m |x| |v|, the most P and L could be
  /// (a body spinning in place has P = 0, yet each particle carries m |v|).
  double linear_scale = 0.0, angular_scale = 0.0;
};
Momentum momentum(const Model& model, const State& state);

/// |P1 - P0| and |L1 - L0| against the larger of the two states' scales; 0 when both are at rest.
struct MomentumChange {
  double linear = 0.0, angular = 0.0;
};
MomentumChange momentum_change(const Momentum& from, const Momentum& to);

/// Kept: a change within this of its scale, rounding over a run's steps (a double's 1e-16 a
/// particle, a step, summed over thousands of either).
inline constexpr double kMomentumKept = 1e-9;
/// Broken for all to see: a change of a thousandth of its scale (a conjugate-gradient solve's
/// 1e-5 is not; VBD's 10 sweeps on a stiff cloth, 0.45, is).
inline constexpr double kMomentumVisible = 1e-3;

}  // namespace springlab
