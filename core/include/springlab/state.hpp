// The State: what an integrator advances. Positions and velocities are N x 3 column-major
// matrices, so each coordinate (all x, all y, all z) is one contiguous array: structure of
// arrays, which is what lets the spring loop vectorise. Row i is particle i.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace springlab {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // column-major: x | y | z

struct State {
  Points x;        // positions, m
  Points v;        // velocities, m/s
  double t = 0.0;  // time, s

  int particle_count() const { return static_cast<int>(x.rows()); }
  void resize(int n) {
    x.resize(n, 3);
    v.resize(n, 3);
  }
};

// A hash of the exact bits of a state (positions, velocities and time): equal hashes mean
// bit-identical states. FNV-1a over the raw doubles.
std::uint64_t state_hash(const State& state);

bool all_finite(const State& state);

}  // namespace springlab
