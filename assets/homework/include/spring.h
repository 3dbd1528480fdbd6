// The rope exercise's spring.h, as the exercise declares it: its rest length is the distance
// between its masses when it is made.
#ifndef SPRING_H
#define SPRING_H

#include "CGL/CGL.h"
#include "mass.h"

using namespace std;

namespace CGL {

struct Spring {
  Spring(Mass *a, Mass *b, float k) : k(k), rest_length((a->position - b->position).norm()), m1(a), m2(b) {}

  float k;
  double rest_length;

  Mass *m1;
  Mass *m2;
};  // struct Spring

}  // namespace CGL

#endif /* SPRING_H */
