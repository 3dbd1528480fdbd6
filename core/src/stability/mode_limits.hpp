// The methods' limits on one damped mode x'' = -kappa x - gamma x' in closed form, for their
// rows in the method table (mode_stability.cpp derives each).
#pragma once

namespace springlab::modes {

double euler(double gamma, double kappa, double verlet_damping);
double modified_euler(double gamma, double kappa, double verlet_damping);
double symplectic_euler(double gamma, double kappa, double verlet_damping);
double verlet(double gamma, double kappa, double verlet_damping);

}  // namespace springlab::modes
