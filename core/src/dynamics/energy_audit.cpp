#include "springlab/energy_audit.hpp"

#include <algorithm>
#include <cmath>

namespace springlab {

void EnergyAudit::reset() {
  open_empty_ = true;
  windows_ = 0;
  lowest_.reset();
  pending_.clear();
  last_exceeded_ = -2;
}

void EnergyAudit::record(double t, std::int64_t step, double net, double total, double floor) {
  if (open_empty_) {
    open_ = Window{{net, total, t, step}, net, t, 0};
    open_empty_ = false;
  }
  if (net < open_.low.net) open_.low = {net, total, t, step};
  open_.high = std::max(open_.high, net);
  if (++open_.checks < kChecks || t - open_.t0 < window_) return;
  open_empty_ = true;
  const std::int64_t index = windows_++;
  if (lowest_ && open_.high - lowest_->net > floor) {
    // Bounded: a run that never gets its analysis keeps the latest.
    if (pending_.size() >= 4096) pending_.erase(pending_.begin());
    pending_.push_back({index, open_.high, *lowest_});
  }
  if (!lowest_ || open_.low.net < lowest_->net) lowest_ = open_.low;
}

std::optional<EnergyAudit::Finding> EnergyAudit::decide(const Allowance& allowance, double floor) {
  std::optional<Finding> found;
  for (const Rise& r : pending_) {
    // The energy of motion at the low (infinite where nothing bounds the energy from below), and
    // what a stable step lets N rise to: margin (G - 1) U, nothing at all when G = 1.
    const double motion = std::max(r.before.total - allowance.lowest_energy, 0.0);
    const double allowed =
        allowance.growth > 1.0 ? kMargin * (allowance.growth - 1.0) * motion : 0.0;
    const double rise = r.high - r.before.net;
    if (!(rise > allowed + floor)) continue;
    const bool in_a_row = r.index == last_exceeded_ + 1;
    last_exceeded_ = r.index;
    if (!in_a_row || found) continue;
    Finding f;
    f.rise = rise;
    f.allowed = allowed + floor;
    f.motion = motion;
    f.growth = allowance.growth;
    f.low_step = r.before.step;
    f.low_t = r.before.t;
    found = f;
  }
  pending_.clear();
  return found;
}

}  // namespace springlab
