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
// (midpoint and modified Euler create less; near its limit RK4 creates more: in general a mode
// multiplied by rho^2 a step by the method and by e^(-c h) by the physics gives
// (rho^2 - e^(-c h)) / (1 - rho^2) of the fall).
// An unstable method, growing or saturated, keeps what it creates. So, looking every second of simulated time (and at least every eight
// checks), a run is numerically unstable when, since the first look, the created energy has
// risen by more than the threshold and by more than twice that bound (r from the stability
// analysis; past an exact limit, any rise past the threshold counts). A symplectic method's
// energy swings by up to tenfold near its limit (and comes back): for them the energy is the
// modified one they keep (simulation.cpp).
#pragma once

#include <cstdint>
#include <optional>

#include "springlab/methods.hpp"
#include "springlab/stability.hpp"

namespace springlab {

class EnergyAudit {
 public:
  static constexpr double kWindow = 1.0;  // s
  static constexpr int kChecks = 8;
  // The allowance K (what a stable method may create per joule that stays gone) is known only
  // from the analysis, which the audit asks for only when something looks wrong; meanwhile it
  // keeps, for each K of this ladder, the lower envelope of S = created + K net per window
  // (S stays level or falls for a stable method whose allowance is at most K).
  static constexpr int kLadder = 14;
  static constexpr double kAllowances[kLadder] = {0, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};

  struct Stretch {
    double rise[kLadder] = {};  // J, of each S's envelope since the first window
    std::int64_t step = 0;      // where it started
    double t = 0.0;
    // The rise for an allowance K: that of the least ladder K at or above it (never stricter).
    double rise_for(double allowance) const;
  };

  void reset();
  // One check: the time and step, the energy created so far and net. Returns the stretch since
  // the first window whenever a window closes (from the second on).
  std::optional<Stretch> record(double t, std::int64_t step, double created, double net);

 private:
  struct Envelope {
    double t = 0.0;
    std::int64_t step = 0;
    double lowest[kLadder] = {};
    int checks = 0;
  };
  Envelope first_, open_;
  bool have_first_ = false, open_empty_ = true;
};

// How many times the fall of net a stable method at step h may create: twice what its limiting
// mode gives, (rho^2 - e^(-c h)) / (1 - rho^2) with rho the method's amplification of that mode
// and c its damping (for explicit Euler, r / (1 - r) with r = h / h*); 0 past an exact limit.
double allowed_creation_ratio(Method method, double h, const StabilityLimit& limit, double verlet_damping);

}  // namespace springlab
