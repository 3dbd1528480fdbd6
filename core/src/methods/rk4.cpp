// The classic fourth-order Runge-Kutta method:
//   k1 = F(y), k2 = F(y + h/2 k1), k3 = F(y + h/2 k2), k4 = F(y + h k3)
//   y1 = y + h/6 (k1 + 2 k2 + 2 k3 + k4)
#include "runge_kutta.hpp"
#include "steps.hpp"

namespace springlab::steps {

void rk4(const Model& model, const State& in, State& out, double h, const StepSettings&,
         Workspace& ws) {
  const Tableau& tableau = *method_info(Method::RK4).tableau;  // the row's own (table.cpp)
  rk::stages(model, in.x, in.v, h, tableau, ws);
  rk::combine(in.x, in.v, h, tableau.b, ws, out.x, out.v);
  out.t = in.t + h;
}

}  // namespace springlab::steps
