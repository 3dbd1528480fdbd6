#include "springlab/energy.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "dynamics/threads.hpp"
#include "springlab/simd.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace {

// Sums over particles [begin, end) with sixteen running sums (four vectors) in a fixed order:
// independent add chains (one chain is bound by the adder's latency), and the same bits every
// time. `term.template operator()<T>(i)` is the contribution of particle i (T = double) or of
// particles i .. i + 3 (T = simd::f64x4), its three coordinates summed in the term.
template <typename Term>
double lane_sum(int begin, int end, const Term& term) {
  using simd::f64x4;
  f64x4 acc[4] = {};
  int i = begin;
  for (; i + 16 <= end; i += 16)
    for (int j = 0; j < 4; ++j) acc[j] += term.template operator()<f64x4>(i + 4 * j);
  double rest = 0.0;
  for (; i < end; ++i) rest += term.template operator()<double>(i);
  return simd::sum((acc[0] + acc[1]) + (acc[2] + acc[3])) + rest;
}

}  // namespace

namespace {

// Pieces of a sum: this many springs or particles each, summed by the threads where the whole is
// worth them (threads.hpp), each piece's sum in its own fixed order, then the pieces' sums in
// order: the same bits for any number of threads.
constexpr int kPiece = 4096;

template <typename Part>
double ordered_sum(int pieces, const Part& part) {
  std::vector<double> parts(static_cast<std::size_t>(pieces));
  threads::for_each_piece(pieces, static_cast<double>(pieces) * kPiece,
                          [&](int p) { parts[p] = part(p); });
  double sum = 0.0;
  for (double v : parts) sum += v;
  return sum;
}

int pieces_of(int count) {
  return (count + kPiece - 1) / kPiece;
}

// sum k_s (l - L)^2 / 2 over springs [lo, hi) (in the order finalize() left them), span by span
// in chunks whose terms are summed with four running sums (in a fixed order).
double spring_energy_sum(const Model& model, const State& state, int lo, int hi) {
  constexpr int kChunk = 256;
  const double* X = state.x.col(0).data();
  const double* Y = state.x.col(1).data();
  const double* Z = state.x.col(2).data();
  double acc[4] = {0.0, 0.0, 0.0, 0.0};
  double term[kChunk];
  // The span holding spring lo: the last whose first spring is not after it.
  auto span = std::upper_bound(model.spans.begin(), model.spans.end(), lo,
                               [](int s, const SpringSpan& sp) { return s < sp.first; }) -
              1;
  for (; span < model.spans.end() && span->first < hi; ++span) {
    const double half_ks = 0.5 * model.materials[span->material].ks;
    const int from = std::max(lo - span->first, 0), to = std::min(hi - span->first, span->count);
    for (int first = from; first < to; first += kChunk) {
      const int count = std::min(kChunk, to - first);
      const int a = span->a0 + first, b = span->b0 + first;
      for (int k = 0; k < count; ++k) {
        const double dx = X[b + k] - X[a + k], dy = Y[b + k] - Y[a + k], dz = Z[b + k] - Z[a + k];
        const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - span->rest;
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

double spring_energy_sum(const Model& model, const State& state) {
  const int springs = model.spring_count();
  return ordered_sum(pieces_of(springs), [&](int p) {
    return spring_energy_sum(model, state, p * kPiece, std::min(springs, (p + 1) * kPiece));
  });
}

// lane_sum over all particles, piece by piece.
template <typename Term>
double particle_sum(int n, const Term& term) {
  return ordered_sum(pieces_of(n), [&](int p) {
    return lane_sum(p * kPiece, std::min(n, (p + 1) * kPiece), term);
  });
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
  e.gravity = -particle_sum(n, [&]<typename T>(int i) {
    using simd::at;
    return simd::where_greater(at<T>(w + i), 0.0, at<T>(m + i)) *
           (g[0] * at<T>(x[0] + i) + g[1] * at<T>(x[1] + i) + g[2] * at<T>(x[2] + i));
  });
  e.spring = spring_energy_sum(model, state);
  for (const Attractor& field : model.attractors)
    for (int i = 0; i < n; ++i)
      if (w[i] > 0.0) e.field += m[i] * field_potential(field, state.x.row(i).transpose());
  return e;
}

double kinetic_energy(const Model& model, const State& state) {
  return probe(model, state).kinetic;
}

StepProbe probe(const Model& model, const State& state) {
  const int n = model.particle_count();
  StepProbe p;
  p.kinetic = ordered_sum(pieces_of(n), [&](int k) {
    return probe(model, state, k * kPiece, std::min(n, (k + 1) * kPiece)).kinetic;
  });
  p.finite = std::isfinite(p.kinetic);
  return p;
}

StepProbe probe(const Model& model, const State& state, int begin, int end) {
  const double* m = model.mass.data();
  const double* w = model.inv_mass.data();
  const double* x[3] = {state.x.col(0).data(), state.x.col(1).data(), state.x.col(2).data()};
  const double* v[3] = {state.v.col(0).data(), state.v.col(1).data(), state.v.col(2).data()};
  // One sum of probe_term() (energy.hpp): finiteness rides along with the kinetic energy.
  StepProbe p;
  p.kinetic = 0.5 * lane_sum(begin, end, [&]<typename T>(int i) {
                using simd::at;
                const T vi[3] = {at<T>(v[0] + i), at<T>(v[1] + i), at<T>(v[2] + i)};
                const T xi[3] = {at<T>(x[0] + i), at<T>(x[1] + i), at<T>(x[2] + i)};
                return probe_term(at<T>(w + i), at<T>(m + i), vi, xi);
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
    power +=
        model.drag * lane_sum(0, model.particle_count(), [&]<typename T>(int i) {
          using simd::at;
          const T vx = at<T>(v[0] + i), vy = at<T>(v[1] + i), vz = at<T>(v[2] + i);
          return simd::where_greater(
              at<T>(w + i), 0.0, vx * (vx - wind[0]) + vy * (vy - wind[1]) + vz * (vz - wind[2]));
        });
  }
  return power;
}

double wind_power(const Model& model, const State& state) {
  if (model.drag == 0.0 || model.wind.isZero()) return 0.0;
  double power = 0.0;
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) power += model.wind.dot(state.v.row(i).transpose());
  return model.drag * power;
}

double field_power(const Model& model, const State& state) {
  double power = 0.0;
  for (const Attractor& f : model.attractors) {
    if (f.swirl == 0.0) continue;
    Attractor swirl = f;
    swirl.strength = 0.0;  // the pull is conservative: only the swirl's work
    for (int i = 0; i < model.particle_count(); ++i)
      if (!model.pinned(i))
        power +=
            model.mass[i] *
            field_acceleration(swirl, state.x.row(i).transpose()).dot(state.v.row(i).transpose());
  }
  return power;
}

Vec3 held_force(const Model& model, const State& state, int particle,
                const std::vector<int>& springs) {
  Vec3 f = Vec3::Zero();
  for (int s : springs) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 fa = spring_force(state.x.row(a).transpose(), state.x.row(b).transpose(),
                                 state.v.row(a).transpose(), state.v.row(b).transpose(),
                                 model.ks(s), model.kd(s), model.rest_length[s]);
    f += a == particle ? fa : Vec3(-fa);
  }
  return f;
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
