// What an iterative method (XPBD, local-global, vertex block descent) pays at a large step, in
// place of a stability limit: artificial damping (energy taken out beyond the physics' damping,
// which the run's energy account gives: E0 + W - E - dissipated) and softness (at rest under a
// load, its springs stretch further than the spring model's at the same load).
#pragma once

#include <optional>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

// The RMS over the springs with stiffness of their stretch l - L (m).
double rms_stretch(const Model& model, const State& state);

// At rest: the kinetic energy at most 1e-6 of the scene's energy scale (energy.hpp), or of its
// weight's, sum m |g| times its extent, where that is smaller.
bool at_rest(const Model& model, const State& state, double energy_scale);

// Whether the energy account's remainder, E0 + W - E - dissipated, is the method's own: only
// where no collider acts. Contacts' impacts and friction take energy the account does not count
// apart (the jelly on its ground, 8 s: symplectic Euler's remainder -11 J, VBD's -9.7 J; the
// chain, 20 s, no collider: symplectic Euler's 8e-5 J, VBD's 0.30 J, its own damping).
inline bool energy_account_closed(const Model& model) {
  return !model.has_colliders();
}

// Springs' lengths over their rest lengths, sum l / sum L over the springs with stiffness: a
// chain's length against its own (2: it hangs at twice its length).
double length_ratio(const Model& model, const State& state);

// Whether the springs carry a load to pins, so that a settled state has a balance to be held to
// (softness, below): gravity acts, no collider or field takes any of it, and every free particle
// is joined by springs to a pinned one. A free body, or one resting on the ground, has none: its
// springs carry no load, and "acts as k_s x" means nothing there.
bool loaded_balance(const Model& model);

// A settled state's stretch against the spring model's at the same load (loaded_balance only): its
// equilibrium (stability.hpp) from `settled`. Under a load the stretch goes as 1 / k, so the
// springs act as if their stiffness were k_s * ratio().
struct Softness {
  double stretch = 0.0;        // m, RMS, the settled state's
  double model_stretch = 0.0;  // m, RMS, the spring model's equilibrium's
  double ratio() const { return stretch > 0.0 ? model_stretch / stretch : 1.0; }
};
Softness softness(const Model& model, const State& settled);

// Local-global's plain iteration's spectral radius on a step of h from `state`, measured (a power
// method over `iterations` from the prediction). Chebyshev acceleration (--rho) past it
// overshoots the fixed point and puts energy in (the chain at rho 0.999, one step a frame), so
// the command line and the app warn when --rho exceeds it.
double local_global_radius(const Model& model, const State& state, double h, int iterations = 64);

}  // namespace springlab
