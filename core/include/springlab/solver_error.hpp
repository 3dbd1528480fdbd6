// The solver error of the methods that solve implicit Euler's step by iterations (docs/numerics.md,
// "The methods practitioners use"), kept apart from their time-stepping error: one step of h from
// a state, each method cut at k iterations, against the converged backward-Euler step from the
// same state. The time-stepping error (against the true motion) is the sweep's (sweep.hpp).
//
//   error_k = |x_k - x*| / |x* - x|        RMS over the free particles, x the state stepped from
//
// x* is vertex block descent run until its step satisfies m (v1 - v) / h = f(x1, v1) to 1e-10 of
// the largest force, checked with the force pass (the residual is reported). Implicit Euler's
// conjugate gradients are charted for reference, capped at k iterations: their step is the
// backward-Euler step linearised once, so their error levels off at the linearisation's.
#pragma once

#include <string>
#include <vector>

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct SolverErrorCurve {
  Method method = Method::LocalGlobal;
  std::vector<int> iterations;  // XPBD: passes; implicit Euler: conjugate-gradient iterations
  std::vector<double> error;    // relative, as above
  std::string note;             // what a reader should know of the curve, e.g. why it levels off
};

struct SolverErrorStudy {
  double h = 0.0;
  double motion = 0.0;    // m: the RMS of x* - x over the free particles
  double residual = 0.0;  // of x*: the largest |m (v1 - v) / h - f| over the largest |f|
  std::vector<SolverErrorCurve> curves;  // local-global, VBD, XPBD, implicit Euler
};

// Up to max_iterations (1, 2, 4, ... ); `settings` gives the rest (local-global's rho).
SolverErrorStudy solver_error(const Model& model, const State& state, double h,
                              int max_iterations = 64, const StepSettings& settings = {});

}  // namespace springlab
