// expect: pass
// expect-euler: euler
// expect-verlet: verlet
// expect-says: damping along the relative velocity, f_b = -k_d (v_b - v_a), k_d = 0.5 N s/m
// Damping along the relative velocity, not projected on the spring: half the velocity difference
// pulls both ends together. Explicit Euler (the position with the old velocity), no global drag.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
  auto delta = (1.0 / (num_nodes - 1)) * (end - start);
  for (int i = 0; i < num_nodes; i++) {
    auto position = start + i * delta;
    masses.emplace_back(new Mass(position, node_mass, false));
    if (i > 0) springs.emplace_back(new Spring(masses[i - 1], masses[i], k));
  }
  for (auto i : pinned_nodes) masses[i]->pinned = true;
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
  for (auto& s : springs) {
    auto d = s->m2->position - s->m1->position;
    auto d_norm = d.norm();
    auto f_ab = s->k * (d / d_norm) * (d_norm - s->rest_length);
    auto damping = 0.5 * (s->m2->velocity - s->m1->velocity);
    s->m1->forces += f_ab + damping;
    s->m2->forces -= f_ab + damping;
  }
  for (auto& m : masses) {
    if (!m->pinned) {
      m->forces += gravity * m->mass;
      auto a = m->forces / m->mass;
      m->position += m->velocity * delta_t;
      m->velocity += a * delta_t;
    }
    m->forces = Vector2D(0, 0);
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
  for (auto& s : springs) {
    auto d = s->m2->position - s->m1->position;
    auto d_norm = d.norm();
    auto f_ab = s->k * (d / d_norm) * (d_norm - s->rest_length);
    s->m1->forces += f_ab;
    s->m2->forces -= f_ab;
  }
  for (auto& m : masses) {
    if (!m->pinned) {
      auto temp_position = m->position;
      m->forces += gravity * m->mass;
      m->position = m->position + (1 - 0.00005) * (m->position - m->last_position) +
                    (m->forces / m->mass) * delta_t * delta_t;
      m->last_position = temp_position;
    }
    m->forces = Vector2D(0, 0);
  }
}

}  // namespace CGL
