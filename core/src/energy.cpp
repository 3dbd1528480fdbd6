#include "springlab/energy.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/spring_kernel.hpp"

namespace springlab {

Energy energy(const Model& model, const State& state) {
  Energy e;
  const int n = model.particle_count();
  for (int i = 0; i < n; ++i) {
    if (model.pinned(i)) continue;
    const double m = model.mass[i];
    e.kinetic += 0.5 * m * state.v.row(i).squaredNorm();
    e.gravity -= m * model.gravity.dot(state.x.row(i).transpose());
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    e.spring += spring_energy(state.x.row(a).transpose(), state.x.row(b).transpose(), model.ks(s),
                              model.rest_length[s]);
  }
  return e;
}

double kinetic_energy(const Model& model, const State& state) {
  double e = 0.0;
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) e += 0.5 * model.mass[i] * state.v.row(i).squaredNorm();
  return e;
}

double dissipation_power(const Model& model, const State& state) {
  double power = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    const double kd = model.kd(s);
    if (kd == 0.0) continue;
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 d = (state.x.row(b) - state.x.row(a)).transpose();
    const double l = d.norm();
    if (coincident(l, model.rest_length[s])) continue;
    const double rate = (state.v.row(b) - state.v.row(a)).dot(d.transpose()) / l;
    power += kd * rate * rate;
  }
  if (model.drag > 0.0)
    for (int i = 0; i < model.particle_count(); ++i)
      if (!model.pinned(i)) power += model.drag * state.v.row(i).squaredNorm();
  return power;
}

double energy_scale(const Model& model, const State& initial) {
  double floor = 0.0;
  for (int s = 0; s < model.spring_count(); ++s)
    floor += model.ks(s) * model.rest_length[s] * model.rest_length[s];
  if (initial.particle_count() > 0) {
    const Vec3 lo = initial.x.colwise().minCoeff().transpose();
    const Vec3 hi = initial.x.colwise().maxCoeff().transpose();
    const double size = (hi - lo).norm();
    const double g = model.gravity.norm();
    for (int i = 0; i < model.particle_count(); ++i) floor += model.mass[i] * g * size;
  }
  const double scale = std::max(std::abs(energy(model, initial).total()), floor);
  return scale > 0.0 ? scale : 1.0;  // a scene with no energy at all: 1 J
}

}  // namespace springlab
