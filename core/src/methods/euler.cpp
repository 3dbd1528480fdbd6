// Explicit (forward) Euler: both updates from the old state.
//   x1 = x + h v,  v1 = v + h a(x, v)
#include "fused_step.hpp"
#include "steps.hpp"

namespace springlab::steps {

void euler(const Model& model, const State& in, State& out, double h, const StepSettings&,
           Workspace& ws) {
  fused_step(model, in, out, h, ws, [h](auto x, auto v, auto a, auto& x1, auto& v1) {
    x1 = x + h * v;
    v1 = v + h * a;
  });
}

}  // namespace springlab::steps
