// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// A solution with its own headers beside it (rope.h with its damping as members, a destructor and
// a private helper; mass.h with its members reordered and initialised; spring.h with a double k):
// the checker's runner is built against the same headers.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, const vector<int> &pinned_nodes) {
  for (int i = 0; i < num_nodes; ++i) {
    Mass *m = new Mass(start + (end - start) * (double(i) / (num_nodes - 1)), node_mass, false);
    m->id = i;
    masses.push_back(m);
  }
  for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
  for (int i : pinned_nodes) masses[i]->pinned = true;
}

Rope::~Rope() {
  for (Mass *m : masses) delete m;
  for (Spring *s : springs) delete s;
}

void Rope::gather_forces() {
  for (Spring *s : springs) {
    Vector2D f = s->force_on_m1();
    s->m1->forces += f;
    s->m2->forces -= f;
  }
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
  gather_forces();
  for (Mass *m : masses) {
    if (!m->pinned) {
      m->forces -= k_d * m->velocity;
      m->velocity += m->acceleration(gravity) * delta_t;
      m->position += m->velocity * delta_t;
    }
    m->forces = Vector2D(0, 0);
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
  gather_forces();
  for (Mass *m : masses) {
    if (!m->pinned) {
      Vector2D before = m->position;
      m->position += (1 - damping_factor) * (m->position - m->last_position) + m->acceleration(gravity) * delta_t * delta_t;
      m->last_position = before;
    }
    m->forces = Vector2D(0, 0);
  }
}

}  // namespace CGL
