#ifndef SPRING_H
#define SPRING_H

#include "CGL/CGL.h"
#include "mass.h"

using namespace std;

namespace CGL {

// The student's own spring.h: k kept as a double, and the force as a method.
struct Spring {
  Spring(Mass *a, Mass *b, float k) : k(k), rest_length((a->position - b->position).norm()), m1(a), m2(b) {}

  Vector2D force_on_m1() const {
    Vector2D ab = m2->position - m1->position;
    return k * (ab.norm() - rest_length) * ab.unit();
  }

  double k;
  double rest_length;

  Mass *m1;
  Mass *m2;
};

}  // namespace CGL

#endif /* SPRING_H */
