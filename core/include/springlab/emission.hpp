// The live part of emission (emitter.hpp declares the emitters): who is alive, since when, until
// when. It belongs with the state (a reset starts it afresh), and the Simulation keeps it beside
// the state. Births and deaths pin and unpin the pools' particles (model.hpp's set_pinned).
#pragma once

#include <cstdint>
#include <vector>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

// The live part of emission: who is alive, since when, until when. Belongs with the state (a
// reset starts it afresh), kept beside it by the Simulation.
class Emission {
 public:
  Emission() = default;
  // Every pool particle dead; `model` must hold the emitters' pools. Pinned and parked.
  Emission(Model& model, State& state);

  // After a step to state.t: the particles whose lifetime is over die (shells burst), then the
  // emitters give birth to every particle due by state.t. A particle due at t_b < state.t starts
  // where its initial motion under gravity takes it by state.t, so a high rate makes a smooth
  // stream rather than clumps at each step. Returns whether anything was born or died.
  bool update(Model& model, State& state);

  bool empty() const { return born_.empty(); }
  bool owned(int i) const {
    return i < static_cast<int>(owner_.size()) && owner_[i] >= 0;
  }  // in a pool
  bool alive(int i) const { return i < static_cast<int>(born_.size()) && born_[i] == born_[i]; }
  double age(int i, double t) const { return t - born_[i]; }
  double lifetime(int i) const { return lifetime_[i]; }
  const Vec3& color(int i) const { return color_[i]; }
  int alive_count() const { return alive_; }
  std::int64_t dropped() const { return dropped_; }  // births skipped: the pool was full
  std::int64_t born() const { return births_; }

 private:
  struct Stream {
    std::uint64_t state = 0;
    double next();  // uniform in [0, 1)
  };
  struct PoolState {
    std::vector<int> free;  // dead slots, in the order they become free (a FIFO)
    std::size_t head = 0;
  };
  int take(PoolState& pool);
  void give_birth(Model& model, State& state, int i, const Vec3& x, const Vec3& v, double born,
                  double lifetime, const Vec3& color, const Spawn& spawn);
  void kill(Model& model, State& state, int i);
  Vec3 direction(const Spawn& spawn, Stream& s);

  std::vector<double> born_;  // NaN: dead (or not an emitted particle)
  std::vector<double> lifetime_;
  std::vector<Vec3> color_;
  std::vector<int> owner_;  // emitter index, or -1
  std::vector<bool> spark_;
  std::vector<Stream> streams_;        // one per emitter
  std::vector<std::int64_t> emitted_;  // births due so far, per emitter (dropped included)
  std::vector<PoolState> pools_, bursts_;
  int alive_ = 0;
  std::int64_t dropped_ = 0, births_ = 0;
};

}  // namespace springlab
