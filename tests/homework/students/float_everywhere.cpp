// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: float's rounding
// Float throughout, as the exercise's own types invite (float k, float delta_t, float mass): the
// fraction along the rope, every length and every force's size computed in float.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
    for (int i = 0; i < num_nodes; i++) {
        float t = (float)i / (float)(num_nodes - 1);
        masses.push_back(new Mass(start + (end - start) * t, node_mass, false));
    }
    for (int i = 1; i < num_nodes; i++) {
        springs.push_back(new Spring(masses[i - 1], masses[i], k));
    }
    for (auto &i : pinned_nodes) masses[i]->pinned = true;
}

static void hooke(vector<Spring *> &springs) {
    for (auto &s : springs) {
        Vector2D ab = s->m2->position - s->m1->position;
        float len = ab.norm();
        float rest = s->rest_length;
        float size = s->k * (len - rest);
        Vector2D f = ab / len * size;
        s->m1->forces += f;
        s->m2->forces -= f;
    }
}

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
    hooke(springs);
    float kd = 0.01f;
    for (auto &m : masses) {
        if (!m->pinned) {
            m->forces += gravity * m->mass - kd * m->velocity;
            Vector2D a = m->forces / m->mass;
            m->velocity += a * delta_t;
            m->position += m->velocity * delta_t;
        }
        m->forces = Vector2D(0, 0);
    }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
    hooke(springs);
    float damping = 0.00005f;
    for (auto &m : masses) {
        if (!m->pinned) {
            Vector2D temp_position = m->position;
            Vector2D a = m->forces / m->mass + gravity;
            m->position = m->position + (1.0f - damping) * (m->position - m->last_position) + a * delta_t * delta_t;
            m->last_position = temp_position;
        }
        m->forces = Vector2D(0, 0);
    }
}

}
