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

// At rest: the kinetic energy at most 1e-6 of the scene's energy scale (energy.hpp).
bool at_rest(const Model& model, const State& state, double energy_scale);

// A settled state's stretch against the spring model's at the same load: its equilibrium
// (stability.hpp) from `settled`. Under a load the stretch goes as 1 / k, so the springs act as
// if their stiffness were k_s * ratio().
struct Softness {
  double stretch = 0.0;        // m, RMS, the settled state's
  double model_stretch = 0.0;  // m, RMS, the spring model's equilibrium's
  double ratio() const { return stretch > 0.0 ? model_stretch / stretch : 1.0; }
};
Softness softness(const Model& model, const State& settled);

}  // namespace springlab
