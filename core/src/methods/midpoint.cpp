// Midpoint: an Euler half step to the middle, then the whole step with the derivative there.
//   y_mid = y + h/2 F(y),  y1 = y + h F(y_mid)
#include "runge_kutta.hpp"
#include "steps.hpp"

namespace springlab::steps {

void midpoint(const Model& model, const State& in, State& out, double h, const StepSettings&,
              Workspace& ws) {
  const Tableau& tableau = *method_info(Method::Midpoint).tableau;  // the row's own (table.cpp)
  rk::stages(model, in.x, in.v, h, tableau, ws);
  rk::combine(in.x, in.v, h, tableau.b, ws, out.x, out.v);
  out.t = in.t + h;
}

}  // namespace springlab::steps
