#ifndef MASS_H
#define MASS_H

#include "CGL/CGL.h"
#include "CGL/vector2D.h"

using namespace CGL;

// The student's own mass.h: its members in another order than the exercise's (positions first),
// each with a default initialiser, and a helper of its own.
struct Mass {
  Mass(Vector2D position, float mass, bool pinned)
      : start_position(position), position(position), last_position(position), mass(mass), pinned(pinned) {}

  Vector2D start_position;
  Vector2D position;
  Vector2D last_position;
  Vector2D velocity = Vector2D(0, 0);
  Vector2D forces = Vector2D(0, 0);

  float mass = 1.0f;
  bool pinned = false;
  int id = -1;

  Vector2D acceleration(Vector2D gravity) const { return forces / mass + gravity; }
};

#endif /* MASS_H */
