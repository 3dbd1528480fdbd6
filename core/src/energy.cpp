#include "springlab/energy.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace {

// Sums over particles [begin, end) with sixteen running sums in a fixed order: independent add
// chains (one chain is bound by the adder's latency) that the compiler turns into vectors, and
// the same bits every time. term(i, c) is the contribution of coordinate c of particle i.
template <typename Term>
double lane_sum(int begin, int end, const Term& term) {
  constexpr int kLanes = 16;
  double acc[kLanes] = {};
  for (int c = 0; c < 3; ++c) {
    int i = begin;
    for (; i + kLanes <= end; i += kLanes)
      for (int j = 0; j < kLanes; ++j) acc[j] += term(i + j, c);
    for (; i < end; ++i) acc[0] += term(i, c);
  }
  for (int width = kLanes / 2; width > 0; width /= 2)
    for (int j = 0; j < width; ++j) acc[j] += acc[j + width];
  return acc[0];
}

}  // namespace

namespace {

// sum k_s (l - L)^2 / 2 over the springs, span by span, in chunks whose terms are summed with
// four running sums (in a fixed order: the same bits every time).
double spring_energy_sum(const Model& model, const State& state) {
  constexpr int kChunk = 256;
  const double* X = state.x.col(0).data();
  const double* Y = state.x.col(1).data();
  const double* Z = state.x.col(2).data();
  double acc[4] = {0.0, 0.0, 0.0, 0.0};
  double term[kChunk];
  for (const SpringSpan& span : model.spans) {
    const double half_ks = 0.5 * model.materials[span.material].ks;
    for (int lo = 0; lo < span.count; lo += kChunk) {
      const int count = std::min(kChunk, span.count - lo);
      const int a = span.a0 + lo, b = span.b0 + lo;
      for (int k = 0; k < count; ++k) {
        const double dx = X[b + k] - X[a + k], dy = Y[b + k] - Y[a + k], dz = Z[b + k] - Z[a + k];
        const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - span.rest;
        term[k] = half_ks * stretch * stretch;
      }
      int k = 0;
      for (; k + 4 <= count; k += 4)
        for (int j = 0; j < 4; ++j) acc[j] += term[k + j];
      for (; k < count; ++k) acc[0] += term[k];
    }
  }
  return (acc[0] + acc[1]) + (acc[2] + acc[3]);
}

}  // namespace

Energy energy(const Model& model, const State& state) {
  Energy e;
  const int n = model.particle_count();
  e.kinetic = kinetic_energy(model, state);
  const double* m = model.mass.data();
  const double* w = model.inv_mass.data();
  const double* x[3] = {state.x.col(0).data(), state.x.col(1).data(), state.x.col(2).data()};
  const double g[3] = {model.gravity.x(), model.gravity.y(), model.gravity.z()};
  e.gravity = -lane_sum(0, n, [&](int i, int c) { return (w[i] > 0.0 ? m[i] : 0.0) * g[c] * x[c][i]; });
  e.spring = spring_energy_sum(model, state);
  for (const Attractor& field : model.attractors)
    for (int i = 0; i < n; ++i)
      if (w[i] > 0.0) e.field += m[i] * field_potential(field, state.x.row(i).transpose());
  return e;
}


double kinetic_energy(const Model& model, const State& state) {
  return probe(model, state, 0, model.particle_count()).kinetic;
}

StepProbe probe(const Model& model, const State& state) {
  return probe(model, state, 0, model.particle_count());
}

StepProbe probe(const Model& model, const State& state, int begin, int end) {
  const double* m = model.mass.data();
  const double* w = model.inv_mass.data();
  const double* x[3] = {state.x.col(0).data(), state.x.col(1).data(), state.x.col(2).data()};
  const double* v[3] = {state.v.col(0).data(), state.v.col(1).data(), state.v.col(2).data()};
  // One sum: x * 0 is 0 for every finite x and NaN otherwise, so it adds nothing to the kinetic
  // energy unless a position is not finite; a velocity that is not finite makes the sum so too
  // (0 * inf is NaN: pinned ones count as well).
  StepProbe p;
  p.kinetic = 0.5 * lane_sum(begin, end, [&](int i, int c) {
                return (w[i] > 0.0 ? m[i] : 0.0) * v[c][i] * v[c][i] + x[c][i] * 0.0;
              });
  p.finite = std::isfinite(p.kinetic);
  return p;
}

StepProbe& StepProbe::operator+=(const StepProbe& block) {
  finite = finite && block.finite;
  kinetic += block.kinetic;
  return *this;
}

double dissipation_power(const Model& model, const State& state) {
  // sum k_d ((v_b - v_a) . d)^2 / l^2 over the damped springs, span by span in chunks (vectorised,
  // as spring_energy_sum), then k_drag v . (v - wind) over the free particles.
  constexpr int kChunk = 256;
  const double* x[3] = {state.x.col(0).data(), state.x.col(1).data(), state.x.col(2).data()};
  const double* v[3] = {state.v.col(0).data(), state.v.col(1).data(), state.v.col(2).data()};
  double acc[4] = {0.0, 0.0, 0.0, 0.0};
  double term[kChunk];
  for (const SpringSpan& span : model.spans) {
    const double kd = model.materials[span.material].kd;
    if (kd == 0.0) continue;
    // Coincident ends (l <= kCoincident max(L, 1)) compared squared: no square root needed.
    const double coincident = kCoincident * std::max(span.rest, 1.0);
    const double coincident2 = coincident * coincident;
    for (int lo = 0; lo < span.count; lo += kChunk) {
      const int count = std::min(kChunk, span.count - lo);
      const int a = span.a0 + lo, b = span.b0 + lo;
      for (int k = 0; k < count; ++k) {
        double l2 = 0.0, rate = 0.0;
        for (int c = 0; c < 3; ++c) {
          const double d = x[c][b + k] - x[c][a + k];
          l2 += d * d;
          rate += (v[c][b + k] - v[c][a + k]) * d;
        }
        term[k] = l2 > coincident2 ? kd * rate * rate / l2 : 0.0;
      }
      int k = 0;
      for (; k + 4 <= count; k += 4)
        for (int j = 0; j < 4; ++j) acc[j] += term[k + j];
      for (; k < count; ++k) acc[0] += term[k];
    }
  }
  double power = (acc[0] + acc[1]) + (acc[2] + acc[3]);
  if (model.drag > 0.0) {
    const double* w = model.inv_mass.data();
    const double wind[3] = {model.wind.x(), model.wind.y(), model.wind.z()};
    power += model.drag * lane_sum(0, model.particle_count(), [&](int i, int c) {
               return w[i] > 0.0 ? v[c][i] * (v[c][i] - wind[c]) : 0.0;
             });
  }
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
  // Emitted particles: as many as the pools hold, at their fastest, thrown up against gravity
  // (m v^2 covers their kinetic energy and the height they can gain), and as deep in a well.
  const auto pool_floor = [&](const Spawn& spawn, const Pool& pool) {
    const double v = spawn.speed + spawn.speed_spread + model.wind.norm();
    double well = 0.0;
    for (const Attractor& f : model.attractors) well += std::abs(f.strength) / f.softening;
    return pool.capacity * spawn.mass * (v * v + well);
  };
  for (const Emitter& e : model.emitters) {
    floor += pool_floor(e.spawn, e.pool);
    if (e.burst) floor += pool_floor(e.burst->spawn, e.burst->pool);
  }
  const double scale = std::max(std::abs(energy(model, initial).total()), floor);
  return scale > 0.0 ? scale : 1.0;  // a scene with no energy at all: 1 J
}

}  // namespace springlab
