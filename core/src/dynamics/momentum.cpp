#include "springlab/momentum.hpp"

#include <algorithm>

namespace springlab {

bool free_body(const Model& model) {
  if (model.gravity != Vec3::Zero() || model.drag != 0.0 || !model.attractors.empty() ||
      !model.emitters.empty() || model.has_colliders())
    return false;
  for (int i = 0; i < model.particle_count(); ++i)
    if (model.pinned(i)) return false;
  return model.particle_count() > 0;
}

Momentum momentum(const Model& model, const State& state) {
  Momentum m;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    const Vec3 x = state.x.row(i).transpose(), v = state.v.row(i).transpose();
    m.linear += model.mass[i] * v;
    m.angular += model.mass[i] * x.cross(v);
    m.linear_scale += model.mass[i] * v.norm();
    m.angular_scale += model.mass[i] * x.norm() * v.norm();
  }
  return m;
}

MomentumChange momentum_change(const Momentum& from, const Momentum& to) {
  const auto relative = [](double change, double scale) {
    return scale > 0.0 ? change / scale : 0.0;
  };
  return {
      relative((to.linear - from.linear).norm(), std::max(from.linear_scale, to.linear_scale)),
      relative((to.angular - from.angular).norm(), std::max(from.angular_scale, to.angular_scale))};
}

}  // namespace springlab
