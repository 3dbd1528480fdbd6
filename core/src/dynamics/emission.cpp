#include "springlab/emission.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace springlab {

namespace {

constexpr double kDead = std::numeric_limits<double>::quiet_NaN();

// An orthonormal pair across a unit vector.
void basis(const Vec3& n, Vec3& u, Vec3& w) {
  u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  w = n.cross(u);
}

// A particle's lifetime: spawn.lifetime give or take spawn.lifetime_spread, uniformly (one draw
// from the emitter's stream `s`, an Emission::Stream), never below 0.
template <typename Stream>
double spawn_lifetime(const Spawn& spawn, Stream& s) {
  return std::max(0.0, spawn.lifetime + spawn.lifetime_spread * (2.0 * s.next() - 1.0));
}

// A particle's speed: spawn.speed give or take spawn.speed_spread, uniformly (one draw).
template <typename Stream>
double spawn_speed(const Spawn& spawn, Stream& s) {
  return spawn.speed + spawn.speed_spread * (2.0 * s.next() - 1.0);
}

// One of `colors`, each as likely (one draw); white where there are none.
template <typename Stream>
Vec3 spawn_color(const std::vector<Vec3>& colors, Stream& s) {
  if (colors.empty()) return Vec3(Vec3::Ones());
  const auto k = std::min(colors.size() - 1, static_cast<std::size_t>(s.next() * colors.size()));
  return colors[k];
}

}  // namespace

// SplitMix64 (Steele, Lea and Flood 2014): tiny, fast, and the same numbers on every platform,
// unlike the standard library's distributions. 53 random bits make a double in [0, 1).
double Emission::Stream::next() {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

Emission::Emission(Model& model, State& state) {
  const int n = model.particle_count();
  born_.assign(n, kDead);
  lifetime_.assign(n, 0.0);
  color_.assign(n, Vec3::Ones());
  owner_.assign(n, -1);
  spark_.assign(n, false);
  const std::size_t emitters = model.emitters.size();
  streams_.resize(emitters);
  emitted_.assign(emitters, 0);
  pools_.resize(emitters);
  bursts_.resize(emitters);
  const auto prepare = [&](const Pool& pool, PoolState& free, int owner, bool spark,
                           const Vec3& at) {
    for (int i = pool.first; i < pool.first + pool.capacity; ++i) {
      free.free.push_back(i);
      owner_[i] = owner;
      spark_[i] = spark;
      set_pinned(model, i, true);
      state.x.row(i) = at.transpose();
      state.v.row(i).setZero();
    }
  };
  for (std::size_t k = 0; k < emitters; ++k) {
    const Emitter& e = model.emitters[k];
    // Distinct emitters with one seed still get distinct streams.
    streams_[k].state = e.seed * 0x2545F4914F6CDD1Dull + k;
    prepare(e.pool, pools_[k], static_cast<int>(k), false, e.position);
    if (e.burst) prepare(e.burst->pool, bursts_[k], static_cast<int>(k), true, e.position);
  }
}

int Emission::take(PoolState& pool) {
  if (pool.head == pool.free.size()) return -1;
  const int i = pool.free[pool.head++];
  // Compact now and then so that the queue does not grow without bound.
  if (pool.head > 1024 && pool.head * 2 > pool.free.size()) {
    pool.free.erase(pool.free.begin(), pool.free.begin() + static_cast<std::ptrdiff_t>(pool.head));
    pool.head = 0;
  }
  return i;
}

Vec3 Emission::direction(const Spawn& spawn, Stream& s) {
  // Uniform over the spherical cap of half-angle `cone`: cos(theta) uniform in [cos(cone), 1].
  const double c = 1.0 - s.next() * (1.0 - std::cos(spawn.cone));
  const double phi = 2.0 * std::numbers::pi * s.next();
  const double r = std::sqrt(std::max(0.0, 1.0 - c * c));
  Vec3 u, w;
  basis(spawn.direction, u, w);
  return c * spawn.direction + r * (std::cos(phi) * u + std::sin(phi) * w);
}

void Emission::give_birth(Model& model, State& state, int i, const Vec3& x, const Vec3& v,
                          double born, double lifetime, const Vec3& color, const Spawn& spawn) {
  // Born at `born`, shown at state.t: its free flight under gravity in between (drag and fields
  // are left out of this fraction of a step).
  const double tau = state.t - born;
  model.mass[i] = spawn.mass;
  set_pinned(model, i, false);
  state.x.row(i) = (x + tau * v + (0.5 * tau * tau) * model.gravity).transpose();
  state.v.row(i) = (v + tau * model.gravity).transpose();
  born_[i] = born;
  lifetime_[i] = lifetime;
  color_[i] = color;
  ++alive_;
  ++births_;
}

void Emission::kill(Model& model, State& state, int i) {
  set_pinned(model, i, true);
  state.v.row(i).setZero();
  born_[i] = kDead;
  --alive_;
  (spark_[i] ? bursts_ : pools_)[owner_[i]].free.push_back(i);
}

bool Emission::update(Model& model, State& state) {
  const double t = state.t;
  bool changed = false;
  // Deaths, in particle order; a shell's sparks are born where and when it died.
  const int n = static_cast<int>(born_.size());
  for (int i = 0; i < n; ++i) {
    if (!alive(i) || t - born_[i] < lifetime_[i]) continue;
    const double died = born_[i] + lifetime_[i];
    const Vec3 x = state.x.row(i).transpose(), v = state.v.row(i).transpose();
    const int k = owner_[i];
    const bool shell = !spark_[i] && model.emitters[k].burst.has_value();
    kill(model, state, i);
    changed = true;
    if (!shell) continue;
    const Emitter::Burst& burst = *model.emitters[k].burst;
    Stream& s = streams_[k];
    const Vec3 color = spawn_color(burst.colors, s);
    for (int c = 0; c < burst.count; ++c) {
      const Vec3 dir = direction(burst.spawn, s);
      const double v0 = spawn_speed(burst.spawn, s);
      const double life = spawn_lifetime(burst.spawn, s);
      const int j = take(bursts_[k]);
      if (j < 0) {
        ++dropped_;
        continue;
      }
      give_birth(model, state, j, x, v + v0 * dir, died, life, color, burst.spawn);
    }
  }

  // Births due by t: the j-th at start + j / rate.
  for (std::size_t k = 0; k < model.emitters.size(); ++k) {
    const Emitter& e = model.emitters[k];
    if (!(e.rate > 0.0) || t < e.start) continue;
    const auto due =
        static_cast<std::int64_t>(std::floor((std::min(t, e.stop) - e.start) * e.rate)) + 1;
    // More than the pool can hold at once would only be dropped: skip them without drawing.
    if (due - emitted_[k] > e.pool.capacity) {
      dropped_ += due - emitted_[k] - e.pool.capacity;
      emitted_[k] = due - e.pool.capacity;
    }
    Stream& s = streams_[k];
    Vec3 u, w;
    basis(e.spawn.direction, u, w);
    for (; emitted_[k] < due; ++emitted_[k]) {
      const double born = e.start + static_cast<double>(emitted_[k]) / e.rate;
      Vec3 x = e.position;
      if (e.shape == EmitterShape::Disc) {
        // Uniform over the disc: r = R sqrt(U).
        const double r = e.radius * std::sqrt(s.next()), phi = 2.0 * std::numbers::pi * s.next();
        x += r * (std::cos(phi) * u + std::sin(phi) * w);
      } else if (e.shape == EmitterShape::Ball) {
        // Uniform in the ball: a uniform direction, r = R cbrt(U).
        const Spawn all{.direction = Vec3::UnitY(), .cone = std::numbers::pi};
        x += e.radius * std::cbrt(s.next()) * direction(all, s);
      }
      const Vec3 dir = direction(e.spawn, s);
      const double v0 = spawn_speed(e.spawn, s);
      const double life = spawn_lifetime(e.spawn, s);
      const Vec3 color = spawn_color(e.colors, s);
      const int i = take(pools_[k]);
      if (i < 0) {
        ++dropped_;
        continue;
      }
      give_birth(model, state, i, x, v0 * dir, born, life, color, e.spawn);
      changed = true;
    }
  }
  return changed;
}

}  // namespace springlab
