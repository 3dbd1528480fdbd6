// Modified Euler, the lecture notes' form: the position moves with the average of the old and
// the new velocity, the velocity takes an Euler step.
//   v1 = v + h a(x, v),  x1 = x + h (v + v1) / 2  ( = x + h v + h^2 a / 2 )
// The position is second order per step, the velocity is not, so the method is first order.
#include "fused_step.hpp"
#include "steps.hpp"

namespace springlab::steps {

void modified_euler(const Model& model, const State& in, State& out, double h, const StepSettings&,
                    Workspace& ws) {
  fused_step(model, in, out, h, ws, [h](auto x, auto v, auto a, auto& x1, auto& v1) {
    v1 = v + h * a;
    x1 = x + (0.5 * h) * (v + v1);
  });
}

}  // namespace springlab::steps
