// A rope solution with hooks for the usual mistakes: each file beside it defines one of the
// macros below and includes this, so each file is a rope.cpp with exactly one mistake planted
// (tests/cli/homework_test.cpp checks the checker names it). With none defined it is correct.
//   EXPLICIT              simulateEuler is explicit Euler (correct too: the exercise asks for both)
//   NO_DAMPING            neither step damps (correct)
//   UNEVEN                masses spaced by i / num_nodes instead of i / (num_nodes - 1)
//   FORCES_KEPT           forces never cleared
//   ONE_END               the spring force on m1 only
//   WRONG_SIGN            f = -k (|b - a| - l) (b - a)/|b - a| on m1
//   NO_REST_LENGTH        f = k (b - a)
//   PIN_FALLS             gravity and motion for pinned masses too
//   LAST_STALE            Verlet never advances last_position
//   DAMPING_PER_SPRING    the damping applied in the springs' loop, once per spring
//   CRASH                 simulateVerlet reads past the end of the masses
//   ENDLESS               simulateVerlet loops forever
//   THROWS                simulateEuler throws
//   PRINTS                both steps print to standard output (correct: the checker's replies are elsewhere)
//   CONSTRAINTS           simulateVerlet holds the springs as constraints, CS 184's way (correct too)
#include <iostream>
#include <stdexcept>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
  for (int i = 0; i < num_nodes; ++i) {
#ifdef UNEVEN
    Vector2D position = start + (end - start) * (double(i) / num_nodes);
#else
    Vector2D position = start + (end - start) * (double(i) / (num_nodes - 1));
#endif
    masses.push_back(new Mass(position, node_mass, false));
  }
  for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
  for (auto& i : pinned_nodes) masses[i]->pinned = true;
}

namespace {

#ifdef NO_DAMPING
const double kd = 0.0, damping_factor = 0.0;
#else
const double kd = 0.01, damping_factor = 0.00005;
#endif

void spring_forces(vector<Spring*>& springs) {
  for (auto& s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
#ifdef NO_REST_LENGTH
    Vector2D f = s->k * ab;
#else
    Vector2D f = s->k * ab.unit() * (ab.norm() - s->rest_length);
#endif
#ifdef WRONG_SIGN
    f = -f;
#endif
    s->m1->forces += f;
#ifndef ONE_END
    s->m2->forces -= f;
#endif
  }
}

bool moves(const Mass* m) {
#ifdef PIN_FALLS
  (void)m;
  return true;
#else
  return !m->pinned;
#endif
}

}  // namespace

void Rope::simulateEuler(float delta_t, Vector2D gravity) {
#ifdef THROWS
  throw std::runtime_error("not written yet");
#endif
#ifdef PRINTS
  std::cout << "simulateEuler: " << masses.size() << " masses, first at " << masses[0]->position << std::endl;
#endif
  spring_forces(springs);
  for (auto& m : masses) {
    if (moves(m)) {
      m->forces += gravity * m->mass;
      m->forces += -kd * m->velocity;
      Vector2D a = m->forces / m->mass;
#ifdef EXPLICIT
      m->position += m->velocity * delta_t;
      m->velocity += a * delta_t;
#else
      m->velocity += a * delta_t;
      m->position += m->velocity * delta_t;
#endif
    }
#ifndef FORCES_KEPT
    m->forces = Vector2D(0, 0);
#endif
  }
}

void Rope::simulateVerlet(float delta_t, Vector2D gravity) {
#ifdef ENDLESS
  for (volatile int i = 0; i >= 0; i = (i + 1) % 2) {
  }
#endif
#ifdef CRASH
  Mass* far = masses[masses.size() + (1 << 28)];
  far->position = Vector2D(1, 1);
#endif
#ifdef PRINTS
  std::cout << "simulateVerlet: 1.0 2.0 ok\nstate 3" << std::endl;
#endif
#ifndef CONSTRAINTS
  spring_forces(springs);
#endif
#ifdef DAMPING_PER_SPRING
  // The damping inside the springs' loop: a mass with two springs is damped twice.
  std::vector<int> count(masses.size(), 0);
  for (auto& s : springs)
    for (size_t i = 0; i < masses.size(); ++i)
      if (masses[i] == s->m1 || masses[i] == s->m2) ++count[i];
#endif
  for (size_t i = 0; i < masses.size(); ++i) {
    Mass* m = masses[i];
    if (moves(m)) {
      Vector2D temp_position = m->position;
      Vector2D a = m->forces / m->mass + gravity;
      double d = damping_factor;
#ifdef DAMPING_PER_SPRING
      d = damping_factor * count[i];
#endif
      m->position = m->position + (1 - d) * (m->position - m->last_position) + a * delta_t * delta_t;
#ifndef LAST_STALE
      m->last_position = temp_position;
#endif
    }
#ifndef FORCES_KEPT
    m->forces = Vector2D(0, 0);
#endif
  }
#ifdef CONSTRAINTS
  // One pass over the springs, each put back at its rest length: half each way, or all on the
  // free end of a pinned one.
  for (auto& s : springs) {
    Vector2D ab = s->m2->position - s->m1->position;
    Vector2D correction = ab.unit() * (ab.norm() - s->rest_length);
    if (!s->m1->pinned && !s->m2->pinned) {
      s->m1->position += 0.5 * correction;
      s->m2->position -= 0.5 * correction;
    } else if (!s->m1->pinned) {
      s->m1->position += correction;
    } else if (!s->m2->pinned) {
      s->m2->position -= correction;
    }
  }
#endif
}

}  // namespace CGL
