// Adaptive Euler, the lecture notes' step doubling. From the state y, with internal step T:
//   x_T    one Euler step of size T
//   x_T/2  two Euler steps of size T/2
//   error  max over particles of |x_T - x_T/2|
// While the error is above the tolerance, halve T and try again; keep the two-half-step result;
// double T for the next step when the error is well under (below 1/8 of) the tolerance, since
// Euler's local error grows as T^2.
//
// Cost: x_T/2 needs only a(y) (its second half step moves x with the half-step velocity), so a
// rejected try costs no force evaluation; an accepted one costs one more, a(y_T/2), for the
// velocity, and its end state's a(y) starts the next try: 2 evaluations per accepted step.
#include <algorithm>
#include <cmath>

#include "adaptive.hpp"
#include "step_scratch.hpp"
#include "steps.hpp"

namespace springlab::steps {

void adaptive_euler(const Model& model, const State& in, State& out, double h,
                    const StepSettings& settings, Workspace& ws) {
  out.x = in.x;
  out.v = in.v;
  StepScratch& s = scratch(ws);
  if (s.stage_dv.size() < 2) s.stage_dv.resize(2);
  Points& a0 = s.stage_dv[0];
  Points& a1 = s.stage_dv[1];
  double T = adaptive::first_try(ws, h);
  double done = 0.0;
  accelerations(model, out.x, out.v, a0, ws);
  while (done < h) {
    const double remaining = h - done;
    const bool last = T >= remaining * (1.0 - 1e-12);
    const double step = last ? remaining : T;
    // Whole step (positions only) and the first half step.
    s.trial_x = out.x + step * out.v;          // x_T
    s.stage_x = out.x + (0.5 * step) * out.v;  // x after the first half
    s.stage_v = out.v + (0.5 * step) * a0;     // v after the first half
    // x_T/2 = stage_x + T/2 stage_v, compared with x_T particle by particle.
    double error = 0.0;
    for (int i = 0; i < out.x.rows(); ++i)
      error = std::max(
          error, (s.stage_x.row(i) + (0.5 * step) * s.stage_v.row(i) - s.trial_x.row(i)).norm());
    if (!(error <= settings.tolerance)) {  // also rejects NaN
      ++ws.counters.rejected;
      T = 0.5 * step;
      adaptive::check_floor("adaptive-euler", T, h, settings);
      continue;
    }
    accelerations(model, s.stage_x, s.stage_v, a1, ws);
    out.x = s.stage_x + (0.5 * step) * s.stage_v;
    out.v = s.stage_v + (0.5 * step) * a1;
    done = last ? h : done + step;
    ++ws.counters.accepted;
    // A last step cut short to land on h says nothing against T: T never shrinks to it (a
    // remainder of 1e-14 s left by rounding used to become the next step's first try).
    if (error < settings.tolerance / 8.0)
      T = std::max(T, 2.0 * step);
    else if (!last)
      T = step;
    if (done < h) accelerations(model, out.x, out.v, a0, ws);
  }
  ws.adaptive_step = T;
  out.t = in.t + h;
}

}  // namespace springlab::steps
