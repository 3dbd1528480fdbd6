// Explicit Runge-Kutta methods from their Butcher tableaux, on y = (x, v), y' = (v, a(x, v)):
//   stage i:  y_i = y + h sum_j A[i][j] k_j,   k_i = F(y_i)
//   result:   y + h sum_i b[i] k_i
// The stage derivatives k_i = (stage_dx_i, stage_dv_i) = (v_i, a(x_i, v_i)) are left in the
// workspace's scratch (step_scratch.hpp), stage_dx and stage_dv.
#pragma once

#include "springlab/methods.hpp"
#include "springlab/tableau.hpp"
#include "step_scratch.hpp"

namespace springlab::rk {

// Fills stage_dx[0..stages), stage_dv[0..stages) of scratch(ws) (explicit tableaux; grown to the
// stages) for the step of size h from (x, v). When `first_known` the first stage's derivative is
// already in stage_dx[0], stage_dv[0].
void stages(const Model& model, const Points& x, const Points& v, double h, const Tableau& tableau,
            Workspace& ws, bool first_known = false);

// (x1, v1) = (x, v) + h sum_i w[i] k_i. x1, v1 must not alias x, v.
void combine(const Points& x, const Points& v, double h, const std::vector<double>& weights,
             const StepScratch& s, Points& x1, Points& v1);

}  // namespace springlab::rk
