// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: the lecture's spring damping, along the spring
// expect-says: a global drag f = -c v, c = 0.002 N s/m
// The lecture's own spring damping, projected on the spring, -k_d (b - a)/|b - a| . (v_b - v_a)
// (b - a)/|b - a| (GAMES101 lecture 21), beside a small global drag so that swinging stops too.
#include <iostream>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

    Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes)
    {
        for (int i = 0; i < num_nodes; ++i)
        {
            Vector2D pos = start + (end - start) * ((double)i / ((double)num_nodes - 1.0));
            masses.push_back(new Mass(pos, node_mass, false));
        }
        for (int i = 0; i < num_nodes - 1; ++i)
            springs.push_back(new Spring(masses[i], masses[i + 1], k));
        for (auto &i : pinned_nodes)
            masses[i]->pinned = true;
    }

    void Rope::simulateEuler(float delta_t, Vector2D gravity)
    {
        const double kd = 0.5, drag = 0.002;
        for (auto &s : springs)
        {
            Vector2D ab = s->m2->position - s->m1->position;
            Vector2D dir = ab.unit();
            Vector2D f = s->k * dir * (ab.norm() - s->rest_length);
            // 弹簧内部的阻尼：只阻碍沿弹簧方向的相对运动
            Vector2D v_rel = s->m2->velocity - s->m1->velocity;
            Vector2D damp = -kd * dot(dir, v_rel) * dir;
            s->m1->forces += f - damp;
            s->m2->forces += -f + damp;
        }
        for (auto &m : masses)
        {
            if (!m->pinned)
            {
                m->forces += gravity * m->mass;
                m->forces += -drag * m->velocity;
                m->velocity += m->forces / m->mass * delta_t;
                m->position += m->velocity * delta_t;
            }
            m->forces = Vector2D(0, 0);
        }
    }

    void Rope::simulateVerlet(float delta_t, Vector2D gravity)
    {
        for (auto &s : springs)
        {
            Vector2D ab = s->m2->position - s->m1->position;
            Vector2D f = s->k * ab.unit() * (ab.norm() - s->rest_length);
            s->m1->forces += f;
            s->m2->forces -= f;
        }
        for (auto &m : masses)
        {
            if (!m->pinned)
            {
                Vector2D temp_position = m->position;
                Vector2D a = m->forces / m->mass + gravity;
                m->position = m->position + (1 - 0.00005) * (m->position - m->last_position) + a * delta_t * delta_t;
                m->last_position = temp_position;
            }
            m->forces = Vector2D(0, 0);
        }
    }
}
