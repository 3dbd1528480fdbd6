#include "springlab/iterative_cost.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/energy.hpp"
#include "springlab/stability.hpp"
#include "stability/parts.hpp"

namespace springlab {

double rms_stretch(const Model& model, const State& state) {
  double sum = 0.0;
  int counted = 0;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.ks(s) <= 0.0) continue;
    const double l = (state.x.row(model.spring_b[s]) - state.x.row(model.spring_a[s])).norm();
    sum += (l - model.rest_length[s]) * (l - model.rest_length[s]);
    ++counted;
  }
  return counted > 0 ? std::sqrt(sum / counted) : 0.0;
}

double length_ratio(const Model& model, const State& state) {
  double length = 0.0, rest = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.ks(s) <= 0.0) continue;
    length += (state.x.row(model.spring_b[s]) - state.x.row(model.spring_a[s])).norm();
    rest += model.rest_length[s];
  }
  return rest > 0.0 ? length / rest : 1.0;
}

bool loaded_balance(const Model& model) {
  if (model.gravity == Vec3::Zero() || model.has_colliders() || !model.attractors.empty())
    return false;
  Parts parts(model);
  bool any = false;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    if (!parts.held_part(i)) return false;
    any = true;
  }
  return any;
}

bool at_rest(const Model& model, const State& state, double energy_scale) {
  // Against the weight's scale where there is one, sum m |g| times the scene's extent: a stiff
  // scene's springs' scale, sum k_s L^2, is far larger (a 24 x 24 cloth at k_s = 20000 N/m: 5e5 J,
  // whose 1e-6 let a cloth still swinging at 0.9 m/s count as at rest).
  double weight = 0.0;
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) weight += model.mass[i] * model.gravity.norm();
  if (state.particle_count() > 0)
    weight *= (state.x.colwise().maxCoeff() - state.x.colwise().minCoeff()).norm();
  const double scale = weight > 0.0 ? std::min(energy_scale, weight) : energy_scale;
  return kinetic_energy(model, state) <= 1e-6 * scale;
}

Softness softness(const Model& model, const State& settled) {
  Softness s;
  s.stretch = rms_stretch(model, settled);
  s.model_stretch = rms_stretch(model, equilibrium(model, settled));
  return s;
}

}  // namespace springlab
