// The energy audit, beside the divergence test: whether a run went numerically unstable even
// where nothing blows up (a rope whose fastest sideways modes buzz near the pin, bounded). It
// follows the energy the method created,
//   created = E + D - E0 - W,
// E the total energy, D what damping, drag and contacts took out, E0 the initial energy, W the
// work done from outside (drags, parameter changes, emitters), and the energy that stays,
//   net = E - E0 - W = created - D.
// Created energy alone does not tell an instability: a stable method creates some too, and
// damping takes it out again. On a mode whose limit is h*, explicit Euler at h < h* creates
// r = h / h* of what that mode's damping takes, so over any stretch of a run
//   created <= r / (1 - r) * (the fall of net)
// (midpoint and modified Euler create less; a symplectic method's energy is biased, not
// drifting; RK4 and implicit Euler take energy out). An unstable method, growing or saturated,
// keeps what it creates. So, looking every second of simulated time (and at least every eight
// checks), a run is numerically unstable when, since the first look, the created energy has
// risen by more than the threshold and by more than twice that bound (r from the stability
// analysis; past an exact limit, any rise past the threshold counts). A symplectic method's
// energy swings by up to tenfold near its limit (and comes back): for them the energy is the
// modified one they keep (simulation.cpp).
#pragma once

#include <cstdint>
#include <optional>

namespace springlab {

class EnergyAudit {
 public:
  static constexpr double kWindow = 1.0;  // s
  static constexpr int kChecks = 8;

  struct Stretch {
    double rise = 0.0;  // J, of the created energy's envelope since the first window
    double fall = 0.0;  // J, of net's envelope in that time
    std::int64_t step = 0;  // where it started
    double t = 0.0;
  };

  void reset();
  // One check: the time and step, the energy created so far and net. Returns the stretch since
  // the first window whenever a window closes (from the second on).
  std::optional<Stretch> record(double t, std::int64_t step, double created, double net);

 private:
  struct Envelope {
    double t = 0.0;
    std::int64_t step = 0;
    double created = 0.0, net = 0.0;
    int checks = 0;
  };
  Envelope first_, open_;
  bool have_first_ = false, open_empty_ = true;
};

// How much more than the fall of net a stable method may create at ratio r = h / h* of its
// limit (twice r / (1 - r)); negative when no rise is allowed (past an exact limit).
double allowed_creation_ratio(double h, double limit, bool exact);

}  // namespace springlab
