// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: on the whole displacement
// Verlet with its damping factor on the whole displacement, x + (1 - d) ((x - x_last) + a h^2), a
// form many write from "damp the step"; and an Euler step whose drag is written c v / m in the
// acceleration.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
    Vector2D step = (end - start) / (num_nodes - 1);
    Mass *previous = nullptr;
    for (int i = 0; i < num_nodes; i++) {
        Mass *m = new Mass(start + step * i, node_mass, false);
        masses.push_back(m);
        if (previous) springs.push_back(new Spring(previous, m, k));
        previous = m;
    }
    for (int i : pinned_nodes) masses[i]->pinned = true;
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
    for (Spring *s : springs) {
        Vector2D ab = s->m2->position - s->m1->position;
        double len = ab.norm();
        Vector2D f = s->k * (len - s->rest_length) * ab / len;
        s->m1->forces += f;
        s->m2->forces -= f;
    }
    for (Mass *m : masses) {
        if (!m->pinned) {
            Vector2D a = m->forces / m->mass + gravity - 0.01 * m->velocity / m->mass;
            m->velocity = m->velocity + a * delta_t;
            m->position = m->position + m->velocity * delta_t;
        }
        m->forces = Vector2D(0, 0);
    }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
    for (Spring *s : springs) {
        Vector2D ab = s->m2->position - s->m1->position;
        double len = ab.norm();
        Vector2D f = s->k * (len - s->rest_length) * ab / len;
        s->m1->forces += f;
        s->m2->forces -= f;
    }
    const double d = 0.00005;
    for (Mass *m : masses) {
        if (!m->pinned) {
            Vector2D a = m->forces / m->mass + gravity;
            Vector2D x = m->position;
            m->position = x + (1 - d) * ((x - m->last_position) + a * delta_t * delta_t);
            m->last_position = x;
        }
        m->forces = Vector2D(0, 0);
    }
}

}
