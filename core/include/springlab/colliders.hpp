// Contact with the scene's planes and spheres, applied after each integrator step whatever the
// method: a particle found closer than model.particle_radius to a surface, or inside, is moved
// back out to that distance, its velocity into the surface
// is removed (or reversed by the restitution e), and Coulomb friction takes up to mu times that
// normal impulse from its tangential velocity (all of it when the particle sticks):
//   dv_n = -(1 + e) (v . n)            (only when v . n < 0)
//   v_t <- v_t max(0, 1 - mu dv_n / |v_t|)
#pragma once

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct ContactResult {
  int contacts = 0;           // particles moved or slowed
  double kinetic_lost = 0.0;  // J taken by the inelastic impacts and friction
  // J of gravity's potential gained by moving particles back out (the springs' change is left
  // out: the moves are small, and stretch springs to either side).
  double potential_gained = 0.0;
};

ContactResult resolve_contacts(const Model& model, State& state);

}  // namespace springlab
