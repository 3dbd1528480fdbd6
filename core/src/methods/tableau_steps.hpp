// What a diagonally implicit tableau keeps between steps (tableau_steps.cpp): one implicit Euler
// solver a stage, so that each stage's conjugate gradients (the first guess) start from that
// stage's last answers, and the factorisation of the stages' Newton corrections.
#pragma once

#include <vector>

#include "springlab/methods.hpp"
#include "stage_newton.hpp"

namespace springlab {

struct StageSolvers {
  std::vector<Workspace> solvers;  // one a stage
  steps::NewtonSolver newton;  // Newton's corrections, every stage's (one sparsity: the springs')
  State in, out;               // a stage's start (x~, v~) and its solution (X_i, V_i)
};

}  // namespace springlab
