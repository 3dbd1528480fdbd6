// Energies of a state, and the power lost to the dissipative forces.
//   kinetic    sum m |v|^2 / 2         (free particles; a pinned one has no finite mass to move)
//   spring     sum k_s (l - L)^2 / 2
//   gravity    -sum m g . x            (free particles)
//   field      sum m U(x), U the attractors' potential per unit mass (fields.hpp; free particles)
#pragma once

#include <vector>

#include "springlab/fields.hpp"
#include "springlab/model.hpp"
#include "springlab/simd.hpp"
#include "springlab/state.hpp"

namespace springlab {

/// A state's energies (J): kinetic, spring, gravity and field (the file's opening gives each).
struct Energy {
  double kinetic = 0.0;
  double spring = 0.0;
  double gravity = 0.0;
  double field = 0.0;
  double potential() const { return spring + gravity + field; }
  double total() const { return kinetic + spring + gravity + field; }
};

Energy energy(const Model& model, const State& state);

/// Only the kinetic part: one pass over the particles, no springs (cheap enough for every step).
double kinetic_energy(const Model& model, const State& state);

/// What a simulation checks after every step, in one pass: whether every position and velocity
/// is finite, and the kinetic energy.
struct StepProbe {
  bool finite = true;
  double kinetic = 0.0;
  StepProbe& operator+=(const StepProbe& block);  ///< of the particles that follow
};
StepProbe probe(const Model& model, const State& state);
/// The same over particles [begin, end): a step that has them in cache checks them there.
StepProbe probe(const Model& model, const State& state, int begin, int end);

/// One particle's term of the probe (T = double), or four's (T = simd::f64x4): twice its kinetic
/// energy if free, m |v|^2, plus (x + y + z) * 0, which adds nothing unless a position is not
/// finite, whose NaN then makes the sum so (a velocity that is not finite does so too: 0 * inf is
/// NaN, pinned ones count as well). probe() and the explicit steps' own check share it.
template <typename T>
T probe_term(T inv_mass, T mass, const T v[3], const T x[3]) {
  return simd::where_greater(inv_mass, 0.0, mass) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
         (x[0] + x[1] + x[2]) * 0.0;
}

/// Power (W) taken out by spring damping, sum k_d ((v_b - v_a) . u)^2, and by drag,
/// sum k_drag v . (v - wind) (>= 0 in still air; a wind can put energy in). Integrated over time it
/// is the energy the scene loses physically, as opposed to what an integrator loses or gains
/// numerically.
double dissipation_power(const Model& model, const State& state);

/// Power (W) the fields put in: sum m a_swirl . v over the free particles (a swirl is not a
/// gradient, so it feeds energy in or takes it out; the pull's work is in the potential).
double field_power(const Model& model, const State& state);
/// The power a wind puts in through the drag: k_drag sum wind . v over the free particles (W).
double wind_power(const Model& model, const State& state);

/// The force the springs exert on one particle (with their damping), from its springs' list:
/// what a held particle's prescribed motion works against (its work is -f . v).
Vec3 held_force(const Model& model, const State& state, int particle,
                const std::vector<int>& springs);

/// A scene's energy scale (J), the yardstick of divergence: the larger of |E(initial)| and a
/// floor from the scene itself, sum k_s L^2 + sum m |g| * size (size: the diagonal of the
/// initial bounding box), so that a scene that starts at rest still has a scale.
double energy_scale(const Model& model, const State& initial);

}  // namespace springlab
