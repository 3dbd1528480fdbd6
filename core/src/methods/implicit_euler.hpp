// What implicit_euler.cpp offers besides its step function: the linear system a step solves,
// computed exactly as the step computes it, for the tests to check against an assembled matrix.
#pragma once

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab::implicit_euler_system {

// For the step of h from `in`: Ap = A p and b, with A = M - h df/dv - h^2 df/dx (the definite
// spring Jacobian) and b = h (f + h df/dx v); pinned particles' rows and columns are the identity's
// and their b is zero. Runs on the current thread count.
void evaluate(const Model& model, const State& in, double h, const Points& p, Points& Ap,
              Points& b);

}  // namespace springlab::implicit_euler_system
