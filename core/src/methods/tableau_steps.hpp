// What a diagonally implicit tableau keeps between steps (tableau_steps.cpp): one implicit Euler
// solver a stage, so that each stage's conjugate gradients start from that stage's last answers,
// and the solver of the stages' Newton corrections.
#pragma once

#include <vector>

#include "springlab/methods.hpp"

namespace springlab {

struct StageSolvers {
  std::vector<Workspace> solvers;  // one a stage
  Workspace corrector;             // Newton's corrections, every stage's (their first guess is 0)
  State in, out;                   // a stage's start (x~, v~) and its solution (X_i, V_i)
};

}  // namespace springlab
