// The explicit methods that need one force evaluation a step finish the force pass themselves:
// each thread turns its particles' forces into the new velocity and position as soon as a block
// of them is complete, with the forces summed straight into out.v, and checks them (ws.step_probe)
// in the same loop: no further pass over memory.
//
// update(x, v, a, x1, v1) is one coordinate of particles: position, velocity, acceleration (0 for
// a pinned particle) in; new position and velocity out. A generic lambda, called with doubles
// and with simd::f64x4 (four particles), the same arithmetic either way.
#pragma once

#include "dynamics/force_pass.hpp"
#include "springlab/methods.hpp"
#include "springlab/simd.hpp"
#include "step_scratch.hpp"

namespace springlab::steps {

namespace detail {

// Updates particles [begin, end) from the forces in v1_and_f (overwritten with the new
// velocities) and returns their check, the sum of probe_term() (energy.hpp) over them: finite,
// and twice the kinetic energy of the free ones, summed four particles at a time in a fixed order.
template <typename Update>
StepProbe update_block(const Update& update, const Model& model, const State& in, State& out,
                       double* const v1_and_f[3], int begin, int end) {
  using simd::at;
  using simd::f64x4;
  const double* mass = model.mass.data();
  const double* inv_mass = model.inv_mass.data();
  const double* X[3] = {in.x.col(0).data(), in.x.col(1).data(), in.x.col(2).data()};
  const double* V[3] = {in.v.col(0).data(), in.v.col(1).data(), in.v.col(2).data()};
  double* X1[3] = {out.x.col(0).data(), out.x.col(1).data(), out.x.col(2).data()};
  const auto particles = [&]<typename T>(int i) {
    const T w = at<T>(inv_mass + i);
    T x1[3], v1[3];
    for (int c = 0; c < 3; ++c) {
      update(at<T>(X[c] + i), at<T>(V[c] + i), at<T>(v1_and_f[c] + i) * w, x1[c], v1[c]);
      simd::store(X1[c] + i, x1[c]);
      simd::store(v1_and_f[c] + i, v1[c]);
    }
    return probe_term(w, at<T>(mass + i), v1, x1);
  };
  f64x4 sum{};
  int i = begin;
  for (; i + simd::kLanes <= end; i += simd::kLanes) sum += particles.template operator()<f64x4>(i);
  for (; i < end; ++i) sum[0] += particles.template operator()<double>(i);
  StepProbe probe;
  probe.kinetic = 0.5 * simd::sum(sum);
  probe.finite = std::isfinite(probe.kinetic);
  return probe;
}

}  // namespace detail

template <typename Update>
void fused_step(const Model& model, const State& in, State& out, double h, Workspace& ws,
                const Update update) {
  const int n = model.particle_count();
  out.x.resize(n, 3);
  out.v.resize(n, 3);
  double* const F[3] = {out.v.col(0).data(), out.v.col(1).data(), out.v.col(2).data()};
  const std::size_t blocks = plan_for(model, ws.spring_forces).own.size();
  StepScratch& s = scratch(ws);
  s.block_probes.assign(blocks, StepProbe{});
  s.block_power.resize(blocks);
  force_pass(
      model, in.x, in.v, F, ws.spring_forces,
      [&](int block, int begin, int end) {
        s.block_probes[block] += detail::update_block(update, model, in, out, F, begin, end);
      },
      ws.measure_power ? s.block_power.data() : nullptr);
  StepProbe all;
  for (const StepProbe& block : s.block_probes) all += block;
  ws.step_probe = all;
  if (ws.measure_power) {
    double power = 0.0;
    for (double block : s.block_power) power += block;
    ws.input_power = power;
  }
  ++ws.counters.force_evals;
  out.t = in.t + h;
}

}  // namespace springlab::steps
