// The energy audit, beside the divergence test: whether a run went numerically unstable even
// where nothing blows up (a rope whose fastest sideways modes buzz near the pin, bounded), and
// never calling a stable run unstable. docs/numerics.md, "Instability, told both ways", derives it.
//
// What it watches. The net energy N = E - E0 - W (E the total energy, E0 the initial one, W the
// work done from outside: drags, parameter changes, emitters, contacts' pushes, fields) never
// rises in the physics: damping, drag and friction only take energy out. A method at a finite
// step does not follow that exactly, so a rise of N is not by itself instability. What bounds it:
//
//   On the scene linearised at its balance, a stable step S (spectral radius <= 1) multiplies
//   each mode's energy U = E - E_low (E_low the balance's energy) by at most
//     G = sup_n |S^n|^2   (energy norm; StabilityAnalysis::transient_growth)
//   over any number of steps: G = 1 for a normal contraction, a little above 1 near a limit,
//   large only near critical damping. So for every check m before n,
//     N_n - N_m = U_n - U_m <= (G - 1) U_m.
//   An unstable mode grows without bound, and a saturating one (a buzz) keeps what it gained.
//
// The rule. Checks are gathered in windows (at least kChecks checks and kWindow seconds). When a
// window closes, the highest N in it is compared with the lowest N of each earlier window, m,
// with its energy of motion U_m. The run is numerically unstable when, in two windows in a row,
//     N_max - N_m > 2 (G - 1) U_m + floor        for some earlier window m,
// G over the modes the step keeps stable (a growing mode is the instability itself), 2 a margin
// for the scene's departures from its linearisation, `floor` the audit's fraction of the scene's
// energy scale (rounding, contacts). The run's energy of motion comes from the stability
// analysis' lower bound E_low (lowest_energy()); where there is none, nothing is reported.
//
// Only a window that rises more than the floor above an earlier one needs G and E_low: it waits
// for the stability analysis (pending()), which the audit asks for only then.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace springlab {

class EnergyAudit {
 public:
  static constexpr double kWindow = 0.25;  // s
  static constexpr int kChecks = 8;
  static constexpr double kMargin = 2.0;

  // What a stable run may do, from the stability analysis.
  struct Allowance {
    double growth = 1.0;         // G
    double lowest_energy = 0.0;  // E_low
  };

  // A rise no stable run makes: N rose `rise` J above its low at `low_t` (step `low_step`), where
  // the energy of motion was `motion` J; a stable step allowed `allowed` J.
  struct Finding {
    double rise = 0.0, allowed = 0.0, motion = 0.0, growth = 1.0;
    std::int64_t low_step = 0;
    double low_t = 0.0;
  };

  // Windows of at least `window` seconds (and kChecks checks); a test shortens them to see the
  // audit at work within a short run.
  explicit EnergyAudit(double window = kWindow) : window_(window) {}
  void reset();
  // Windows closed since the last reset().
  std::int64_t windows() const { return windows_; }
  // One check: the time, the step, the net energy N and the total energy E.
  void record(double t, std::int64_t step, double net, double total, double floor);
  // Windows rose more than the floor above an earlier low and wait for a verdict, which needs the
  // stability analysis (asked for only then).
  bool pending() const { return !pending_.empty(); }
  // The verdict on the waiting windows, in order, with the analysis' allowance (the same until
  // reset()). Returns the finding once two windows in a row exceed it.
  std::optional<Finding> decide(const Allowance& allowance, double floor);

 private:
  struct Low {
    double net = 0.0, total = 0.0, t = 0.0;  // N's least, and E there
    std::int64_t step = 0;
  };
  struct Window {
    Low low;
    double high = 0.0;
    double t0 = 0.0;
    int checks = 0;
  };
  // A closed window that rose above the lowest low before it by more than the floor.
  struct Rise {
    std::int64_t index = 0;
    double high = 0.0;
    Low before;
  };
  double window_ = kWindow;
  Window open_;
  bool open_empty_ = true;
  std::int64_t windows_ = 0;  // closed
  // The least N over the closed windows. (Between windows N - E changes only by the outside
  // work, so the earlier low with the least ceiling low + k (E - E_low) is the least low.)
  std::optional<Low> lowest_;
  std::vector<Rise> pending_;
  std::int64_t last_exceeded_ = -2;  // index of the last window over its allowance
};

}  // namespace springlab
