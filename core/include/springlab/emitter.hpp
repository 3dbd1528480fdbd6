// Particle emitters: particles are born at a rate, live for a while and die; a firework's shell
// bursts into sparks when it dies. Every emitter owns a fixed pool of particles in the model
// (its maximum count, checked when the scene loads), so the model never grows: a particle not
// alive is pinned (inverse mass 0), at rest and not drawn, and costs the integrators nothing
// but a pass over a zero. Births beyond the pool are dropped and counted.
//
// Emission is seeded: each emitter draws from its own SplitMix64 stream in a fixed order, so
// the same scene gives the same particles, the same states and the same frames.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace springlab {

using Vec3 = Eigen::Vector3d;

// How a new particle starts: speed and direction (uniform within a cone about `direction`),
// lifetime and mass. Spreads are half-widths of uniform ranges.
struct Spawn {
  double speed = 1.0, speed_spread = 0.0;        // m/s
  Vec3 direction = Vec3::UnitY();                // unit length
  double cone = 0.0;                             // rad, half-angle; pi: every direction
  double lifetime = 1.0, lifetime_spread = 0.0;  // s
  double mass = 0.01;                            // kg
};

// A pool of particles in the model: [first, first + capacity).
struct Pool {
  int first = 0, capacity = 0;
};

enum class EmitterShape { Point, Disc, Ball };

struct Emitter {
  std::string name;
  Vec3 position = Vec3::Zero();
  EmitterShape shape = EmitterShape::Point;
  double radius = 0.0;               // m: of the disc (across `spawn.direction`) or of the ball
  double rate = 0.0;                 // births per second, at start + k / rate
  double start = 0.0, stop = 1e300;  // s: births in [start, stop]
  Spawn spawn;
  Pool pool;
  std::uint64_t seed = 1;
  // Drawing: a colour (r, g, b in [0, 1]) for each particle, picked at birth.
  std::vector<Vec3> colors;
  // Fireworks: a particle of this emitter that dies bursts into `count` sparks from `pool`,
  // which move off with its velocity plus their own; all of one burst share a colour.
  struct Burst {
    int count = 0;
    Spawn spawn;
    Pool pool;
    std::vector<Vec3> colors;
  };
  std::optional<Burst> burst;
};

}  // namespace springlab
