#include "springlab/energy_audit.hpp"

#include <algorithm>
#include <cmath>

namespace springlab {

void EnergyAudit::reset() {
  have_first_ = false;
  open_empty_ = true;
}

std::optional<EnergyAudit::Stretch> EnergyAudit::record(double t, std::int64_t step, double created, double net) {
  if (open_empty_) {
    open_ = {t, step, created, net, 0};
    open_empty_ = false;
  }
  if (++open_.checks < kChecks || t - open_.t < kWindow) return std::nullopt;
  // The window closes here: both quantities taken at the same moment, so that what was created
  // and what stayed are over the same stretch of the run.
  const Envelope closed{t, step, created, net, open_.checks};
  open_empty_ = true;
  if (!have_first_) {
    first_ = closed;
    have_first_ = true;
    return std::nullopt;
  }
  return Stretch{closed.created - first_.created, first_.net - closed.net, first_.step, first_.t};
}

double allowed_creation_ratio(double h, double limit, bool exact) {
  if (std::isnan(limit)) return 1e300;  // chooses its own steps: not audited
  if (std::isinf(limit)) return 0.0;
  const double r = limit > 0.0 ? h / limit : 1e300;
  if (r < 1.0) return 2.0 * r / (1.0 - r);
  return exact ? 0.0 : 100.0;  // past a lower bound: stable or not, it is not known
}

}  // namespace springlab
