// The explicit methods that need one force evaluation a step finish the force pass themselves:
// each thread turns its particles' forces into the new velocity and position at once, with the
// forces summed straight into out.v, instead of in further passes over memory; and checks them
// (ws.step_probe) while they are in cache.
//
// update(x, v, a, x1, v1) is one coordinate of one particle: position, velocity, acceleration
// (0 for a pinned particle) in; new position and velocity out. It is a small value (it holds
// h), so that the loop around it vectorises: nothing it holds can alias the arrays.
#pragma once

#include "../force_pass.hpp"
#include "springlab/methods.hpp"

namespace springlab::steps {

namespace detail {

template <typename Update>
void update_range(const Update update, const double* __restrict x, const double* __restrict v,
                  const double* __restrict inv_mass, double* __restrict x1, double* __restrict v1_and_f,
                  int begin, int end) {
  for (int i = begin; i < end; ++i) {
    double xo, vo;
    update(x[i], v[i], v1_and_f[i] * inv_mass[i], xo, vo);
    x1[i] = xo;
    v1_and_f[i] = vo;
  }
}

}  // namespace detail

template <typename Update>
void fused_step(const Model& model, const State& in, State& out, double h, Workspace& ws,
                const Update update) {
  const int n = model.particle_count();
  out.x.resize(n, 3);
  out.v.resize(n, 3);
  double* const F[3] = {out.v.col(0).data(), out.v.col(1).data(), out.v.col(2).data()};
  ws.block_probes.resize(plan_for(model, ws.spring_forces).own.size());
  force_pass(model, in.x, in.v, F, ws.spring_forces, [&](int block, int begin, int end) {
    for (int c = 0; c < 3; ++c)
      detail::update_range(update, in.x.col(c).data(), in.v.col(c).data(), model.inv_mass.data(),
                           out.x.col(c).data(), F[c], begin, end);
    ws.block_probes[block] = probe(model, out, begin, end);
  });
  StepProbe all;
  for (const StepProbe& block : ws.block_probes) all += block;
  ws.step_probe = all;
  ++ws.counters.force_evals;
  out.t = in.t + h;
}

}  // namespace springlab::steps
