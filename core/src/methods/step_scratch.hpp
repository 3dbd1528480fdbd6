// The step functions' scratch memory, out of the public header: what only the steps in
// src/methods/ read and write. A Workspace holds it (Workspace::scratch), made on the first step
// that asks for it (scratch(ws)) and reused, so that a step allocates nothing once running; a new
// Workspace starts without one.
#pragma once

#include <memory>
#include <vector>

#include "springlab/energy.hpp"
#include "springlab/methods.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct StepScratch {
  /// Runge-Kutta stage derivatives (dx/dt, dv/dt), one a stage (runge_kutta.hpp, rk45.cpp,
  /// tableau_steps.cpp; adaptive-euler keeps a(y) and a(y_T/2) in stage_dv[0] and [1]).
  std::vector<Points> stage_dx, stage_dv;
  /// A stage's state (adaptive Euler: the state after half a step; Verlet: the predicted v(t1)).
  Points stage_x, stage_v;
  Points trial_x, trial_v;  ///< a trial step's result (adaptive methods: kept if accepted)

  /// Whether an embedded pair's first-same-as-last derivative (stage_dx[0], stage_dv[0]) is that
  /// of the state it is given next. Cleared by Workspace::invalidate().
  bool fsal_ready = false;

  /// The fused explicit steps (fused_step.hpp): each block's check and, asked for
  /// (Workspace::measure_power), its dissipated power, summed in block order into
  /// Workspace::step_probe and Workspace::input_power.
  std::vector<StepProbe> block_probes;
  std::vector<double> block_power;
};

/// The workspace's scratch, made on first use.
inline StepScratch& scratch(Workspace& ws) {
  if (!ws.scratch) ws.scratch = std::make_unique<StepScratch>();
  return *ws.scratch;
}

}  // namespace springlab
