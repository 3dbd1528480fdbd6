// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// Leans on what the exercise's CGL/CGL.h brings (<algorithm>, <cmath>, <string>, std::max), with no
// standard headers of its own: the pins found with std::find while the masses are made, std::max
// guarding a zero length, the constants as file-level statics.
#include "CGL/CGL.h"
#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

static const double kDrag = 0.01;
static const double kVerletDamping = 0.00005;

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
  for (int i = 0; i < num_nodes; ++i) {
    bool pinned = std::find(pinned_nodes.begin(), pinned_nodes.end(), i) != pinned_nodes.end();
    masses.push_back(new Mass(start + (end - start) * (double(i) / (num_nodes - 1)), node_mass, pinned));
  }
  for (int i = 1; i < num_nodes; ++i) springs.push_back(new Spring(masses[i - 1], masses[i], k));
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
  for (Spring *s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
    double len = std::max(ab.norm(), EPS_D);
    Vector2D f = (s->k * (len - s->rest_length) / len) * ab;
    s->m1->forces += f;
    s->m2->forces -= f;
  }
  for (Mass *m : masses) {
    if (!m->pinned) {
      Vector2D a = (m->forces - kDrag * m->velocity) / m->mass + gravity;
      m->velocity += a * delta_t;
      m->position += m->velocity * delta_t;
    }
    m->forces = Vector2D();
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
  for (Spring *s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
    double len = std::max(ab.norm(), EPS_D);
    Vector2D f = (s->k * (len - s->rest_length) / len) * ab;
    s->m1->forces += f;
    s->m2->forces -= f;
  }
  for (Mass *m : masses) {
    if (!m->pinned) {
      Vector2D x = m->position;
      m->position += (1 - kVerletDamping) * (x - m->last_position) + (m->forces / m->mass + gravity) * std::pow(delta_t, 2);
      m->last_position = x;
    }
    m->forces = Vector2D();
  }
}

}  // namespace CGL
