// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: damping along the relative velocity, f_b = -k_d (v_b - v_a), k_d = 0.2 N s/m
// CS 184's rope as its staff wrote it: each spring made from the new mass to the previous one,
// the displacement kept in a float, gravity added as an acceleration, the damping along the
// springs' relative velocity, forces cleared at the start of the Verlet step, d = 0.0001.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

    Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass,
               float k, vector<int> pinned_nodes) {
        Vector2D offset = (end - start) / (num_nodes - 1);

        for (int i = 0; i < num_nodes; i++) {
            Vector2D position = start + (i * offset);
            Mass *m = new Mass(position, node_mass, false);

            masses.push_back(m);
            if (i > 0) {
                Spring *s = new Spring(m, masses[i - 1], k);
                springs.push_back(s);
            }
        }

        for (auto &i : pinned_nodes) {
            masses[i]->pinned = true;
        }
    }

    void Rope::simulateEuler(float delta_t, Vector2D gravity) {
        for (auto &s : springs) {
            Vector2D diff = s->m2->position - s->m1->position;
            float displacement = diff.norm() - s->rest_length;

            Vector2D spring_force = displacement * s->k * diff.unit();

            Vector2D relative_velocity = s->m2->velocity - s->m1->velocity;
            Vector2D damping_force = 0.2 * relative_velocity;

            s->m1->forces += (spring_force + damping_force);
            s->m2->forces -= (spring_force + damping_force);
        }

        for (auto &m : masses) {
            if (!m->pinned) {
                m->velocity += (m->forces / m->mass + gravity) * delta_t;
                m->position += m->velocity * delta_t;
            }

            // Reset all forces on each mass
            m->forces = Vector2D(0, 0);
        }
    }

    void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
        // Clear forces
        for (auto &m : masses) {
            m->forces = Vector2D(0, 0);
        }

        for (auto &s : springs) {
            Vector2D diff = s->m2->position - s->m1->position;
            float displacement = diff.norm() - s->rest_length;

            Vector2D spring_force = displacement * s->k * diff.unit();

            s->m1->forces += spring_force;
            s->m2->forces -= spring_force;
        }

        for (auto &m : masses) {
            if (!m->pinned) {
                Vector2D temp_position = m->position;
                m->position += (1 - 0.0001) * (m->position - m->last_position) + (m->forces / m->mass + gravity) * delta_t * delta_t;
                m->last_position = temp_position;
            }
        }
    }
}
