// Semi-implicit (symplectic) Euler: the velocity first, then the position with the new velocity.
//   v1 = v + h a(x, v),  x1 = x + h v1
#include "fused_step.hpp"
#include "steps.hpp"

namespace springlab::steps {

void symplectic_euler(const Model& model, const State& in, State& out, double h,
                      const StepSettings&, Workspace& ws) {
  fused_step(model, in, out, h, ws, [h](auto x, auto v, auto a, auto& x1, auto& v1) {
    v1 = v + h * a;
    x1 = x + h * v1;
  });
}

}  // namespace springlab::steps
