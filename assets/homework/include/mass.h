// The rope exercise's Mass (names and signatures as the exercise's mass.h has them).
#ifndef MASS_H
#define MASS_H

#include "CGL/CGL.h"
#include "CGL/vector2D.h"

using namespace std;

namespace CGL {

struct Mass {
  Mass(Vector2D position, float mass, bool pinned)
      : start_position(position), position(position), last_position(position), mass(mass), pinned(pinned) {}

  Vector2D start_position;
  Vector2D position;

  // explicit Verlet integration
  Vector2D last_position;

  float mass;
  bool pinned;

  // explicit Euler integration
  Vector2D velocity;
  Vector2D forces;
};

}  // namespace CGL

#endif  // MASS_H
