// Shared by the adaptive methods: walking from t to t + h in internal steps of controlled size.
#pragma once

#include <cmath>
#include <string>

#include "springlab/methods.hpp"

namespace springlab::adaptive {

// The internal step to try first: the one the last step ended with, no longer than h.
inline double first_try(const Workspace& ws, double h) {
  return ws.adaptive_step > 0.0 && ws.adaptive_step < h ? ws.adaptive_step : h;
}

// Throws when the controller asks for a step below the floor: a run that needs ever smaller
// steps (it is diverging, or the tolerance is out of reach) must fail, not hang.
inline void check_floor(const char* method, double step, double h, const StepSettings& s) {
  if (step >= s.min_step_fraction * h) return;
  throw StepFailure(std::string(method) + " needed an internal step below " +
                    std::to_string(s.min_step_fraction * h) + " s (h x " +
                    std::to_string(s.min_step_fraction) + ") to meet the tolerance " +
                    std::to_string(s.tolerance) + ": loosen --tol or shorten --dt");
}

// An explicit embedded Runge-Kutta pair stepped from t to t + h under its own control (rk45.cpp):
// each try propagates with b, estimates its error with h sum_s e_s k_s (e = b - b_hat),
//   err = RMS over the free coordinates of h e.k / (tol + tol max(|y|, |y1|)),
// is accepted when err <= 1, and the next try is T min(5, max(0.2, 0.9 err^(-exponent))), never
// growing right after a rejection. With `tableau.first_same_as_last()` the last stage of an
// accepted try is the next one's first. `name` is for the step floor's message.
void embedded_pair_step(const Tableau& tableau, const double* error_weights, double exponent,
                        const char* name, const Model& model, const State& in, State& out, double h,
                        const StepSettings& settings, Workspace& ws);

}  // namespace springlab::adaptive
