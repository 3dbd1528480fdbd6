// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: constraints
// "Explicit Verlet (solving constraints)" read as position-based dynamics: Verlet under gravity
// alone, then a few passes over the springs putting each back at its rest length (a pinned end
// stays, the free end moves all the way). Euler with the drag in the force.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
    Vector2D step = (end - start) / (num_nodes - 1);
    for (int i = 0; i < num_nodes; ++i) masses.push_back(new Mass(start + step * i, node_mass, false));
    for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
    for (int i : pinned_nodes) masses[i]->pinned = true;
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
    for (auto &s : springs) {
        Vector2D d = s->m2->position - s->m1->position;
        Vector2D f = s->k * (d.norm() - s->rest_length) * d.unit();
        s->m1->forces += f;
        s->m2->forces -= f;
    }
    for (auto &m : masses) {
        if (!m->pinned) {
            m->forces += m->mass * gravity - 0.02 * m->velocity;
            m->velocity += m->forces / m->mass * delta_t;
            m->position += m->velocity * delta_t;
        }
        m->forces = Vector2D(0, 0);
    }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
    for (auto &m : masses) {
        if (m->pinned) continue;
        Vector2D temp = m->position;
        m->position += (1 - 0.00005) * (m->position - m->last_position) + gravity * delta_t * delta_t;
        m->last_position = temp;
    }
    for (int pass = 0; pass < 4; ++pass) {
        for (auto &s : springs) {
            Vector2D d = s->m2->position - s->m1->position;
            double len = d.norm();
            Vector2D correction = d * ((len - s->rest_length) / len);
            if (s->m1->pinned && s->m2->pinned) continue;
            if (s->m1->pinned) s->m2->position -= correction;
            else if (s->m2->pinned) s->m1->position += correction;
            else {
                s->m1->position += 0.5 * correction;
                s->m2->position -= 0.5 * correction;
            }
        }
    }
}

}
