// The step functions of the method table (table.cpp), one per file in this folder.
#pragma once

#include "springlab/methods.hpp"

namespace springlab::steps {

#define SPRINGLAB_STEP(fn)                                                                         \
  void fn(const Model& model, const State& in, State& out, double h, const StepSettings& settings, \
          Workspace& ws)

SPRINGLAB_STEP(euler);
SPRINGLAB_STEP(symplectic_euler);
SPRINGLAB_STEP(modified_euler);
SPRINGLAB_STEP(adaptive_euler);
SPRINGLAB_STEP(rk45);
SPRINGLAB_STEP(implicit_euler);
SPRINGLAB_STEP(verlet);
SPRINGLAB_STEP(xpbd);
SPRINGLAB_STEP(local_global);
SPRINGLAB_STEP(vbd);

#undef SPRINGLAB_STEP

// The rows made from tableaux (tableau_steps.cpp).
void explicit_tableau(const Tableau& tableau, const Model& model, const State& in, State& out,
                      double h, const StepSettings& settings, Workspace& ws);
void embedded_pair(const Tableau& tableau, const Model& model, const State& in, State& out,
                   double h, const StepSettings& settings, Workspace& ws);
void diagonally_implicit(const Tableau& tableau, const Model& model, const State& in, State& out,
                         double h, const StepSettings& settings, Workspace& ws);

}  // namespace springlab::steps
