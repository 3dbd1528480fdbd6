// A correct rope: semi-implicit Euler with a global drag, Verlet with a damping factor (the way
// the exercise is usually solved). -DEXPLICIT makes simulateEuler explicit Euler instead.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
  for (int i = 0; i < num_nodes; ++i) {
    Vector2D position = start + (end - start) * (double(i) / (num_nodes - 1));
    masses.push_back(new Mass(position, node_mass, false));
  }
  for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
  for (auto& i : pinned_nodes) masses[i]->pinned = true;
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
  for (auto& s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
    Vector2D f = s->k * ab.unit() * (ab.norm() - s->rest_length);
    s->m1->forces += f;
    s->m2->forces -= f;
  }
  const double kd = 0.01;
  for (auto& m : masses) {
    if (!m->pinned) {
      m->forces += gravity * m->mass;
      m->forces += -kd * m->velocity;
      Vector2D a = m->forces / m->mass;
#ifdef EXPLICIT
      m->position += m->velocity * delta_t;
      m->velocity += a * delta_t;
#else
      m->velocity += a * delta_t;
      m->position += m->velocity * delta_t;
#endif
    }
    m->forces = Vector2D(0, 0);
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
  for (auto& s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
    Vector2D f = s->k * ab.unit() * (ab.norm() - s->rest_length);
    s->m1->forces += f;
    s->m2->forces -= f;
  }
  const double damping_factor = 0.00005;
  for (auto& m : masses) {
    if (!m->pinned) {
      Vector2D temp_position = m->position;
      Vector2D a = m->forces / m->mass + gravity;
      m->position = m->position + (1 - damping_factor) * (m->position - m->last_position) + a * delta_t * delta_t;
      m->last_position = temp_position;
    }
    m->forces = Vector2D(0, 0);
  }
}

}  // namespace CGL
