// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: a global drag on the velocity, a = f / m - c v, c = 0.04 1/s
// The drag written into the acceleration, a = f / m + g - k_d v (a rate: the same for any mass,
// as many write it), kept with the damping factor in one place; forces cleared first, CS 184's way.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

namespace {
const double kDamping = 0.04;        // simulateEuler: a -= k v
const double kVerletDamping = 1e-4;  // simulateVerlet: (1 - d)
}  // namespace

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
    Vector2D offset = (end - start) / (num_nodes - 1);
    for (int i = 0; i < num_nodes; i++) {
        masses.push_back(new Mass(start + i * offset, node_mass, false));
        if (i > 0) springs.push_back(new Spring(masses[i - 1], masses[i], k));
    }
    for (auto &i : pinned_nodes) masses[i]->pinned = true;
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
    for (auto &m : masses) m->forces = Vector2D(0, 0);
    for (auto &s : springs) {
        Vector2D diff = s->m2->position - s->m1->position;
        Vector2D f = s->k * (diff.norm() - s->rest_length) * diff.unit();
        s->m1->forces += f;
        s->m2->forces -= f;
    }
    for (auto &m : masses) {
        if (m->pinned) continue;
        Vector2D a = m->forces / m->mass + gravity - kDamping * m->velocity;
        m->velocity += a * delta_t;
        m->position += m->velocity * delta_t;
    }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
    for (auto &m : masses) m->forces = Vector2D(0, 0);
    for (auto &s : springs) {
        Vector2D diff = s->m2->position - s->m1->position;
        Vector2D f = s->k * (diff.norm() - s->rest_length) * diff.unit();
        s->m1->forces += f;
        s->m2->forces -= f;
    }
    for (auto &m : masses) {
        if (m->pinned) continue;
        Vector2D x = m->position;
        m->position += (1 - kVerletDamping) * (m->position - m->last_position) + (m->forces / m->mass + gravity) * delta_t * delta_t;
        m->last_position = x;
    }
}

}
