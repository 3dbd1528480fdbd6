#include "springlab/energy_audit.hpp"

#include <algorithm>
#include <limits>
#include <cmath>

#include "springlab/stability.hpp"

namespace springlab {

void EnergyAudit::reset() {
  have_first_ = false;
  open_empty_ = true;
}

std::optional<EnergyAudit::Stretch> EnergyAudit::record(double t, std::int64_t step, double created, double net) {
  if (open_empty_) {
    open_ = {t, step, {}, 0};
    for (double& s : open_.lowest) s = std::numeric_limits<double>::infinity();
    open_empty_ = false;
  }
  for (int j = 0; j < kLadder; ++j) open_.lowest[j] = std::min(open_.lowest[j], created + kAllowances[j] * net);
  if (++open_.checks < kChecks || t - open_.t < kWindow) return std::nullopt;
  const Envelope closed = open_;
  open_empty_ = true;
  if (!have_first_) {
    first_ = closed;
    have_first_ = true;
    return std::nullopt;
  }
  Stretch stretch;
  for (int j = 0; j < kLadder; ++j) stretch.rise[j] = closed.lowest[j] - first_.lowest[j];
  stretch.step = first_.step;
  stretch.t = first_.t;
  return stretch;
}

double EnergyAudit::Stretch::rise_for(double allowance) const {
  for (int j = 0; j < kLadder; ++j)
    if (kAllowances[j] >= allowance) return rise[j];
  return -std::numeric_limits<double>::infinity();  // more than the ladder holds: never
}

double allowed_creation_ratio(Method method, double h, const StabilityLimit& limit, double verlet_damping) {
  if (std::isnan(limit.h)) return 1e300;  // chooses its own steps: not audited
  if (std::isinf(limit.h)) return 0.0;    // stable at any step, and dissipative
  if (limit.h == 0.0) return 0.0;
  const bool past = h > limit.h;
  if (past) return limit.exact ? 0.0 : 100.0;  // past a lower bound: stable or not is not known
  if (!limit.mode) {
    const double r = h / limit.h;
    return 2.0 * r / (1.0 - r);
  }
  // The limiting mode's energy is multiplied by rho^2 a step by the method, by e^(-c h) by the
  // physics: the method creates rho^2 - e^(-c h) of it a step while rho^2 is what stays.
  const double rho = amplification(method, limit.mode->w, limit.mode->c, h, verlet_damping);
  if (!(rho < 1.0)) return limit.exact ? 0.0 : 100.0;
  const double created = rho * rho - std::exp(-limit.mode->c * h), fallen = 1.0 - rho * rho;
  return std::max(0.0, 2.0 * created / fallen);
}

}  // namespace springlab
