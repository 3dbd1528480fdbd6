// A rope solution with hooks for the usual mistakes: each file beside it defines one of the
// macros below and includes this, so each file is a rope.cpp with exactly one mistake planted
// (tests/cli/homework_test.cpp checks the checker names it, and nothing else: each file's
// "expect" lines say what a careful reader finds). With none defined it is correct.
//   EXPLICIT              simulateEuler is explicit Euler (correct too: the exercise asks for both)
//   NO_DAMPING            neither step damps (correct)
//   PRINTS                both steps print to standard output (correct: the checker's replies are elsewhere)
//   FACTOR_BEFORE         Euler damped by a factor a step, v = (1 - d) v + a h (correct)
//   FACTOR_NEW            v = (1 - d)(v + a h), then x += v h (correct)
//   FACTOR_AFTER          v += a h, x += v h, then v *= 1 - d (correct)
//   CONSTRAINTS           simulateVerlet holds the springs as constraints, CS 184's way (correct too)
// The constructor:
//   UNEVEN                masses spaced by i / num_nodes instead of i / (num_nodes - 1)
//   REVERSED              the rope laid from end to start
//   INTEGER_DIVISION      i / (num_nodes - 1) divided as integers
//   SPRING_NOT_IN_ROPE    each spring made to a Mass of its own, not the rope's
//   PINS_BEFORE_MASSES    the skeleton's pin loop left before the masses are made
//   PINS_NONE             the skeleton's pin loop left commented out
//   PINS_AS_FLAGS         pinned_nodes read as a flag per node: pinned_nodes[i] past its end
//   DUPLICATE_SPRINGS     every spring made twice
//   END_MASS_MISSING      the last mass made for its spring but never put in masses
//   NULL_MASS             masses sized first, the first slot never filled (a null pointer)
// The steps:
//   FORCES_KEPT           forces never cleared
//   ONE_END               the spring force on m1 only
//   WRONG_SIGN            f = -k (|b - a| - l) (b - a)/|b - a| on m1
//   NO_REST_LENGTH        f = k (b - a)
//   PIN_FALLS             gravity and motion for pinned masses too
//   LAST_STALE            Verlet never advances last_position
//   DAMPING_PER_SPRING    the damping applied in the springs' loop, once per spring
//   ACCEL_TWICE           v += a h, then x += (v + a h) h
//   GRAVITY_NO_MASS       gravity added to the forces without its mass
//   GRAVITY_TIMES_STEP    gravity's force multiplied by the step
//   DRAG_WRONG_SIGN       forces += c v
//   VERLET_A_H            Verlet's acceleration times delta_t, not delta_t^2
//   VERLET_D_SWAPPED      Verlet's (x - x_last) times d instead of (1 - d)
//   CONSTRAINT_NO_GRAVITY the constraint Verlet forgets gravity
//   EULER_NO_DT           v += a, the step left out
//   VELOCITY_NOT_STORED   Euler's new velocity kept in a local, never in the mass
//   SPRING_NO_MASS        the spring force used as an acceleration (gravity and drag right)
//   FORCES_ASSIGNED       forces = f in the springs' loop, not +=
//   VERLET_HALF           Verlet's a h^2 / 2
//   LAST_OVERWRITTEN      Verlet's last_position = position before x_next is computed
// Failures of the code itself:
//   CRASH                 simulateVerlet reads past the end of the masses
//   ENDLESS               simulateVerlet loops forever
//   THROWS                simulateEuler throws
#include <iostream>
#include <stdexcept>
#include <vector>

#include "CGL/vector2D.h"

#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {

Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {
#ifdef PINS_BEFORE_MASSES
  for (auto& i : pinned_nodes) masses[i]->pinned = true;
#endif
#ifdef NULL_MASS
  masses.resize(num_nodes);
#endif
  for (int i = 0; i < num_nodes; ++i) {
#if defined(UNEVEN)
    Vector2D position = start + (end - start) * (double(i) / num_nodes);
#elif defined(REVERSED)
    Vector2D position = end + (start - end) * (double(i) / (num_nodes - 1));
#elif defined(INTEGER_DIVISION)
    Vector2D position = start + (end - start) * (i / (num_nodes - 1));
#else
    Vector2D position = start + (end - start) * (double(i) / (num_nodes - 1));
#endif
#if defined(END_MASS_MISSING)
    if (i + 1 < num_nodes) masses.push_back(new Mass(position, node_mass, false));
    else springs.push_back(new Spring(masses.back(), new Mass(position, node_mass, false), k));
#elif defined(NULL_MASS)
    if (i > 0) masses[i] = new Mass(position, node_mass, false);
#else
    masses.push_back(new Mass(position, node_mass, false));
#endif
  }
#if defined(END_MASS_MISSING)
  for (int i = 0; i + 1 < int(masses.size()); ++i) springs.insert(springs.end() - 1, new Spring(masses[i], masses[i + 1], k));
#elif defined(SPRING_NOT_IN_ROPE)
  for (int i = 0; i + 1 < num_nodes; ++i)
    springs.push_back(new Spring(masses[i], new Mass(masses[i + 1]->position, node_mass, false), k));
#elif !defined(NULL_MASS)
  for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
#endif
#ifdef DUPLICATE_SPRINGS
  for (int i = 0; i + 1 < num_nodes; ++i) springs.push_back(new Spring(masses[i], masses[i + 1], k));
#endif
#if defined(PINS_AS_FLAGS)
  for (int i = 0; i < num_nodes; ++i)
    if (pinned_nodes[i]) masses[i]->pinned = true;
#elif !defined(PINS_BEFORE_MASSES) && !defined(PINS_NONE) && !defined(NULL_MASS)
  for (auto& i : pinned_nodes) masses[i]->pinned = true;
#endif
}

namespace {

#ifdef NO_DAMPING
const double kd = 0.0, damping_factor = 0.0;
#elif defined(DRAG_WRONG_SIGN)
const double kd = -0.01, damping_factor = 0.00005;
#elif defined(VERLET_D_SWAPPED)
const double kd = 0.01, damping_factor = 1.0 - 0.00005;  // (1 - d) written as d: 1 - this is 0.00005
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
#ifdef FORCES_ASSIGNED
    s->m1->forces = f;
    s->m2->forces = -f;
    continue;
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

Vector2D weight(const Mass* m, Vector2D gravity, float delta_t) {
  (void)delta_t;
#if defined(GRAVITY_NO_MASS)
  (void)m;
  return gravity;
#elif defined(GRAVITY_TIMES_STEP)
  return gravity * m->mass * delta_t;
#else
  return gravity * m->mass;
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
#ifdef SPRING_NO_MASS
      Vector2D a = m->forces + gravity - kd * m->velocity / m->mass;
#elif defined(FACTOR_BEFORE) || defined(FACTOR_NEW) || defined(FACTOR_AFTER)
      Vector2D a = m->forces / m->mass + gravity;
#else
      m->forces += weight(m, gravity, delta_t);
      m->forces += -kd * m->velocity;
      Vector2D a = m->forces / m->mass;
#endif
#if defined(EXPLICIT)
      m->position += m->velocity * delta_t;
      m->velocity += a * delta_t;
#elif defined(ACCEL_TWICE)
      m->velocity += a * delta_t;
      m->position += (m->velocity + a * delta_t) * delta_t;
#elif defined(EULER_NO_DT)
      m->velocity += a;
      m->position += m->velocity * delta_t;
#elif defined(VELOCITY_NOT_STORED)
      Vector2D v = m->velocity + a * delta_t;
      m->position += v * delta_t;
#elif defined(FACTOR_BEFORE)
      m->velocity = (1 - damping_factor) * m->velocity + a * delta_t;
      m->position += m->velocity * delta_t;
#elif defined(FACTOR_NEW)
      m->velocity = (1 - damping_factor) * (m->velocity + a * delta_t);
      m->position += m->velocity * delta_t;
#elif defined(FACTOR_AFTER)
      m->velocity += a * delta_t;
      m->position += m->velocity * delta_t;
      m->velocity *= 1 - damping_factor;
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
  Mass* far = *(masses.data() + masses.size() + (1 << 28));  // (past the library's check: a pointer)
  far->position = Vector2D(1, 1);
#endif
#ifdef PRINTS
  std::cout << "simulateVerlet: 1.0 2.0 ok\nstate 3" << std::endl;
#endif
#if !defined(CONSTRAINTS) && !defined(CONSTRAINT_NO_GRAVITY)
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
#ifdef CONSTRAINT_NO_GRAVITY
      Vector2D a = m->forces / m->mass;
#elif defined(SPRING_NO_MASS)
      Vector2D a = m->forces + gravity;
#else
      Vector2D a = m->forces / m->mass + weight(m, gravity, delta_t) / m->mass;
#endif
      double d = damping_factor;
#ifdef DAMPING_PER_SPRING
      d = damping_factor * count[i];
#endif
#ifdef LAST_OVERWRITTEN
      m->last_position = m->position;
#endif
#ifdef VERLET_A_H
      m->position = m->position + (1 - d) * (m->position - m->last_position) + a * delta_t;
#elif defined(VERLET_HALF)
      m->position = m->position + (1 - d) * (m->position - m->last_position) + 0.5 * a * delta_t * delta_t;
#else
      m->position = m->position + (1 - d) * (m->position - m->last_position) + a * delta_t * delta_t;
#endif
#ifndef LAST_STALE
      m->last_position = temp_position;
#endif
    }
#ifndef FORCES_KEPT
    m->forces = Vector2D(0, 0);
#endif
  }
#if defined(CONSTRAINTS) || defined(CONSTRAINT_NO_GRAVITY)
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
