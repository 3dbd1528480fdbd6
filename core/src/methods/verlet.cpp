// Position Verlet, as in the rope exercise, with its damping factor d (model.verlet_damping):
//   x1 = x + (1 - d)(x - x_prev) + h^2 a(x)
// Velocities come from positions: the central difference (x2 - x) / 2h with x2 the next step's
// position, written with the force that the next step needs anyway:
//   v1 = ((2 - d)(x1 - x) + h^2 a(x1)) / 2h
// so a step costs one force evaluation and v1 is second order. The velocity-dependent forces
// (spring damping, drag) in a(x1) see the prediction v(t1) = (x1 - x) / h + h/2 a(x), second
// order too; the half-step velocity (x1 - x) / h alone would make a damped run first order.
//
// Start (and restart after anything changed the state from outside: a contact, a drag, a new h):
//   x_prev = x - h v + h^2/2 a(x, v)
// which is second-order accurate; x_prev = x - h v would make the whole method first order.
// Pinned particles move with their prescribed velocity: x1 = x + h v.
#include "step_scratch.hpp"
#include "steps.hpp"

namespace springlab::steps {

void verlet(const Model& model, const State& in, State& out, double h, const StepSettings&,
            Workspace& ws) {
  const int n = in.particle_count();
  const double d = model.verlet_damping;
  if (!ws.verlet_ready || ws.verlet_h != h) {
    accelerations(model, in.x, in.v, ws.a_now, ws);
    ws.x_prev = in.x - h * in.v + (0.5 * h * h) * ws.a_now;
  }
  out.x = in.x + (1.0 - d) * (in.x - ws.x_prev) + (h * h) * ws.a_now;
  for (int i = 0; i < n; ++i)
    if (model.pinned(i)) out.x.row(i) = in.x.row(i) + h * in.v.row(i);

  Points& v_predicted = scratch(ws).stage_v;
  v_predicted = (out.x - in.x) / h + (0.5 * h) * ws.a_now;  // predicted v(t1)
  accelerations(model, out.x, v_predicted, ws.a_now, ws);
  out.v = ((2.0 - d) * (out.x - in.x) + (h * h) * ws.a_now) / (2.0 * h);
  for (int i = 0; i < n; ++i)
    if (model.pinned(i)) out.v.row(i) = in.v.row(i);

  ws.x_prev = in.x;
  ws.verlet_ready = true;
  ws.verlet_h = h;
  out.t = in.t + h;
}

}  // namespace springlab::steps
