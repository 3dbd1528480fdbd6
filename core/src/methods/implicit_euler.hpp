// What implicit_euler.cpp offers besides its step function: the linear system a step solves,
// computed exactly as the step computes it, for the tests to check against an assembled matrix.
#pragma once

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab::steps {

// Backward Euler solved to convergence: the linearised step, then Newton's corrections until
// M (v1 - v) = h f(x1, v1) to 1e-10 of h times the scene's force scale (implicit_euler.cpp).
// `corrector` holds the corrections' solver (its own, so that `ws`'s first guesses stay the
// steps'); `corrections`, if given, is increased by the corrections made. Throws StepFailure
// naming the residual when 32 corrections do not converge.
void backward_euler_converged(const Model& model, const State& in, State& out, double h, const StepSettings& settings,
                              Workspace& ws, Workspace& corrector, int* corrections = nullptr);

}  // namespace springlab::steps

namespace springlab::implicit_euler_system {

// For the step of h from `in`: Ap = A p and b, with A = M - h df/dv - h^2 df/dx (the definite
// spring Jacobian) and b = h (f + h df/dx v); pinned particles' rows and columns are the identity's
// and their b is zero. Runs on the current thread count.
void evaluate(const Model& model, const State& in, double h, const Points& p, Points& Ap,
              Points& b);

}  // namespace springlab::implicit_euler_system
