// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: a global drag f = -c v, c = 0.005 N s/m
// The most common GAMES101 style: the step vector (end - start) / (num_nodes - 1), Hooke's law
// written from m1's side for each end, the drag folded into the acceleration, Chinese comments.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

    Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes)
    {
        // 质点之间的间隔
        Vector2D step = (end - start) / (num_nodes - 1);
        for (int i = 0; i < num_nodes; ++i)
        {
            masses.push_back(new Mass(start + step * i, node_mass, false));
        }
        for (int i = 0; i < num_nodes - 1; ++i)
        {
            springs.push_back(new Spring(masses[i], masses[i + 1], k));
        }
        for (auto &i : pinned_nodes) {
            masses[i]->pinned = true;
        }
    }

    void Rope::simulateEuler(float delta_t, Vector2D gravity)
    {
        for (auto &s : springs)
        {
            // 胡克定律
            auto len = (s->m1->position - s->m2->position).norm();
            s->m1->forces += -s->k * (s->m1->position - s->m2->position) / len * (len - s->rest_length);
            s->m2->forces += -s->k * (s->m2->position - s->m1->position) / len * (len - s->rest_length);
        }

        const float kd = 0.005;
        for (auto &m : masses)
        {
            if (!m->pinned)
            {
                // 半隐式欧拉：先更新速度，再用新速度更新位置
                auto a = m->forces / m->mass + gravity - kd * m->velocity / m->mass;
                m->velocity += a * delta_t;
                m->position += m->velocity * delta_t;
            }
            // Reset all forces on each mass
            m->forces = Vector2D(0, 0);
        }
    }

    void Rope::simulateVerlet(float delta_t, Vector2D gravity)
    {
        for (auto &s : springs)
        {
            auto len = (s->m1->position - s->m2->position).norm();
            s->m1->forces += -s->k * (s->m1->position - s->m2->position) / len * (len - s->rest_length);
            s->m2->forces += -s->k * (s->m2->position - s->m1->position) / len * (len - s->rest_length);
        }

        const float damping_factor = 0.00005;
        for (auto &m : masses)
        {
            if (!m->pinned)
            {
                Vector2D temp_position = m->position;
                auto a = m->forces / m->mass + gravity;
                m->position = temp_position + (1 - damping_factor) * (temp_position - m->last_position) + a * delta_t * delta_t;
                m->last_position = temp_position;
            }
            m->forces = Vector2D(0, 0);
        }
    }
}
