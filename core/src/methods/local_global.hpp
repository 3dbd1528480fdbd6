// The parts of local_global.cpp's step, for the benchmark of its floor (bench/iterative_bench.cpp):
// one local pass and one pair of triangular solves are what an iteration cannot go below.
#pragma once

#include "iterative.hpp"

namespace springlab::local_global_parts {

// Factorises M~ + sum_s w_s A_s A_s^T for the step h (throws StepFailure if it cannot).
void factorise(const Model& model, double h, const std::vector<double>& mass, LocalGlobalSolver& S);
// The local pass: the right side of the global step for the correction x - y from the iterate X,
// into S.rhs.
void global_rhs(const Model& model, const State& in, double h, const Points& X, const Points& y,
                LocalGlobalSolver& S);
// The global solve: (L D L^T) z = z in place, the factor's order, x y z interleaved.
void solve_in_place(const LocalGlobalSolver& S, std::vector<double>& z);

}  // namespace springlab::local_global_parts
