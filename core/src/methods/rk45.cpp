// Dormand-Prince 5(4): seven stages whose last is the derivative at the new state, reused as the
// first stage of the next internal step (first same as last, so 6 evaluations a step). The
// difference between the fifth- and fourth-order results estimates the local error:
//   err = RMS over coordinates of e_i / (tol + tol max(|y_i|, |y1_i|))
// accepted when err <= 1; the next step is T * min(5, max(0.2, 0.9 err^(-1/5))), and never
// grows right after a rejection (Hairer, Norsett and Wanner, "Solving ODEs I", II.4).
#include <algorithm>
#include <cmath>

#include "adaptive.hpp"
#include "runge_kutta.hpp"
#include "steps.hpp"

namespace springlab::steps {

namespace {

const Tableau kDormandPrince(
    {{0},
     {1.0 / 5.0},
     {3.0 / 40.0, 9.0 / 40.0},
     {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0},
     {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0},
     {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0},
     {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0}},
    {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0, 0.0});

// Fifth-order weights minus the embedded fourth-order ones.
constexpr double kErrorWeights[7] = {
    71.0 / 57600.0,      0.0,          -71.0 / 16695.0, 71.0 / 1920.0,
    -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0};

// RMS of the scaled error over the coordinates of free particles.
double error_norm(const Model& model, const Points& x0, const Points& v0, const Points& x1,
                  const Points& v1, double step, const StepScratch& s, double tol,
                  const double* weights, int stages) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < x0.rows(); ++i) {
    if (model.pinned(i)) continue;
    for (int c = 0; c < 3; ++c) {
      double ex = 0.0, ev = 0.0;
      for (int k = 0; k < stages; ++k) {
        ex += weights[k] * s.stage_dx[k](i, c);
        ev += weights[k] * s.stage_dv[k](i, c);
      }
      const double sx = tol + tol * std::max(std::abs(x0(i, c)), std::abs(x1(i, c)));
      const double sv = tol + tol * std::max(std::abs(v0(i, c)), std::abs(v1(i, c)));
      sum += (step * ex / sx) * (step * ex / sx) + (step * ev / sv) * (step * ev / sv);
      count += 2;
    }
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

}  // namespace

void rk45(const Model& model, const State& in, State& out, double h, const StepSettings& settings,
          Workspace& ws) {
  adaptive::embedded_pair_step(kDormandPrince, kErrorWeights, 0.2, "rk45", model, in, out, h,
                               settings, ws);
}

}  // namespace springlab::steps

namespace springlab::adaptive {

void embedded_pair_step(const Tableau& tableau, const double* error_weights, double exponent,
                        const char* name, const Model& model, const State& in, State& out, double h,
                        const StepSettings& settings, Workspace& ws) {
  const int last_stage = tableau.stages - 1;
  const bool fsal = tableau.first_same_as_last();
  // The state walks in `out`; each try is written to (trial_x, trial_v) and swapped in if
  // accepted.
  StepScratch& s = scratch(ws);
  out.x = in.x;
  out.v = in.v;
  double T = first_try(ws, h);
  double done = 0.0;
  bool first_known = fsal && s.fsal_ready;
  bool just_rejected = false;
  while (done < h) {
    const double remaining = h - done;
    const bool last = T >= remaining * (1.0 - 1e-12);
    const double step = last ? remaining : T;
    rk::stages(model, out.x, out.v, step, tableau, ws, first_known);
    rk::combine(out.x, out.v, step, tableau.b, s, s.trial_x, s.trial_v);
    const double err = steps::error_norm(model, out.x, out.v, s.trial_x, s.trial_v, step, s,
                                         settings.tolerance, error_weights, tableau.stages);
    if (!(err <= 1.0)) {  // also rejects NaN
      ++ws.counters.rejected;
      T = step * (std::isfinite(err) ? std::max(0.2, 0.9 * std::pow(err, -exponent)) : 0.2);
      check_floor(name, T, h, settings);
      first_known = true;  // stage 1 is at the unchanged state
      just_rejected = true;
      continue;
    }
    ++ws.counters.accepted;
    std::swap(out.x, s.trial_x);
    std::swap(out.v, s.trial_v);
    done = last ? h : done + step;
    if (fsal) {  // the last stage was evaluated at the new state: the next step's first
      std::swap(s.stage_dx[0], s.stage_dx[static_cast<std::size_t>(last_stage)]);
      std::swap(s.stage_dv[0], s.stage_dv[static_cast<std::size_t>(last_stage)]);
    }
    first_known = fsal;
    const double growth = err > 0.0 ? 0.9 * std::pow(err, -exponent) : 5.0;
    const double proposal = step * std::clamp(growth, 0.2, just_rejected ? 1.0 : 5.0);
    just_rejected = false;
    // A last step shortened to land on t + h says nothing about the step that fits: keep T
    // unless it must shrink.
    if (!last || proposal < T) T = proposal;
  }
  out.t = in.t + h;
  ws.adaptive_step = T;
  s.fsal_ready = fsal;
}

}  // namespace springlab::adaptive
