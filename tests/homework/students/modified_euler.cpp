// expect: pass
// expect-euler: modified-euler
// expect-verlet: verlet
// The lecture notes' modified Euler in simulateEuler, x += h (v + v_next) / 2, with helper
// functions for the forces; index loops; printf for debugging left in.
#include <cstdio>
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
  for (int i = 0; i < num_nodes; i++) {
    Mass *m = new Mass(start + (end - start) * (i / double(num_nodes - 1)), node_mass, false);
    masses.push_back(m);
  }
  for (size_t i = 0; i + 1 < masses.size(); i++) springs.push_back(new Spring(masses[i], masses[i + 1], k));
  for (size_t j = 0; j < pinned_nodes.size(); j++) masses[pinned_nodes[j]]->pinned = true;
  printf("rope of %d masses\n", num_nodes);
}

static void add_spring_forces(vector<Spring *> &springs) {
  for (size_t i = 0; i < springs.size(); i++) {
    Spring *s = springs[i];
    Vector2D ab = s->m2->position - s->m1->position;
    Vector2D f = s->k * (ab.norm() - s->rest_length) * ab.unit();
    s->m1->forces += f;
    s->m2->forces += -f;
  }
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
  add_spring_forces(springs);
  for (size_t i = 0; i < masses.size(); i++) {
    Mass *m = masses[i];
    if (!m->pinned) {
      Vector2D a = m->forces / m->mass + gravity;
      Vector2D v_next = m->velocity + a * delta_t;
      m->position = m->position + (m->velocity + v_next) * 0.5 * delta_t;
      m->velocity = v_next;
    }
    m->forces = Vector2D(0, 0);
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
  add_spring_forces(springs);
  for (size_t i = 0; i < masses.size(); i++) {
    Mass *m = masses[i];
    if (!m->pinned) {
      Vector2D temp_position = m->position;
      Vector2D a = m->forces / m->mass + gravity;
      m->position = 2 * m->position - m->last_position + a * delta_t * delta_t;
      m->last_position = temp_position;
    }
    m->forces = Vector2D(0, 0);
  }
}

}  // namespace CGL
