// Explicit (forward) Euler: both updates from the old state.
//   x1 = x + h v,  v1 = v + h a(x, v)
#include "steps.hpp"

namespace springlab::steps {

void euler(const Model& model, const State& in, State& out, double h, const StepSettings&,
           Workspace& ws) {
  accelerations(model, in.x, in.v, ws.kv[0], ws);
  out.x = in.x + h * in.v;
  out.v = in.v + h * ws.kv[0];
  out.t = in.t + h;
}

}  // namespace springlab::steps
