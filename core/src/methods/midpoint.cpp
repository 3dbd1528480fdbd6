// Midpoint: an Euler half step to the middle, then the whole step with the derivative there.
//   y_mid = y + h/2 F(y),  y1 = y + h F(y_mid)
#include "runge_kutta.hpp"
#include "steps.hpp"

namespace springlab::steps {

namespace {
constexpr rk::Tableau kMidpoint = {2, {{0}, {0.5}}, {0.0, 1.0}};
}

void midpoint(const Model& model, const State& in, State& out, double h, const StepSettings&,
              Workspace& ws) {
  rk::stages(model, in.x, in.v, h, kMidpoint, ws);
  rk::combine(in.x, in.v, h, kMidpoint.b, kMidpoint.stages, ws, out.x, out.v);
  out.t = in.t + h;
}

}  // namespace springlab::steps
