// The methods' limits on one damped mode x'' = -kappa x - gamma x' in closed form, for their
// rows in the method table (mode_stability.cpp derives each).
#pragma once

#include "springlab/methods.hpp"

namespace springlab::modes {

double euler(double gamma, double kappa, const MethodParameters& parameters);
double modified_euler(double gamma, double kappa, const MethodParameters& parameters);
double symplectic_euler(double gamma, double kappa, const MethodParameters& parameters);
double verlet(double gamma, double kappa, const MethodParameters& parameters);

}  // namespace springlab::modes
