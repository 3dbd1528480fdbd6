// The rope exercise's rope.h, as the exercise declares it: the student writes the constructor and
// the two steps in rope.cpp. The checker calls exactly these (and builds a rope of its own through
// the first constructor when the student's constructor is not yet right).
#ifndef ROPE_H
#define ROPE_H

#include "CGL/CGL.h"
#include "mass.h"
#include "spring.h"

using namespace std;

namespace CGL {

class Rope {
 public:
  Rope(vector<Mass *> &masses, vector<Spring *> &springs) : masses(masses), springs(springs) {}
  Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes);

  void simulateVerlet(float delta_t, Vector2D gravity);
  void simulateEuler(float delta_t, Vector2D gravity);

  vector<Mass *> masses;
  vector<Spring *> springs;
};  // struct Rope

}  // namespace CGL

#endif /* ROPE_H */
