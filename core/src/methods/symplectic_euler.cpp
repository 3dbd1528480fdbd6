// Semi-implicit (symplectic) Euler: the velocity first, then the position with the new velocity.
//   v1 = v + h a(x, v),  x1 = x + h v1
#include "steps.hpp"

namespace springlab::steps {

void symplectic_euler(const Model& model, const State& in, State& out, double h,
                      const StepSettings&, Workspace& ws) {
  accelerations(model, in.x, in.v, ws.kv[0], ws);
  out.v = in.v + h * ws.kv[0];
  out.x = in.x + h * out.v;
  out.t = in.t + h;
}

}  // namespace springlab::steps
