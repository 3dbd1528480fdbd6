#ifndef ROPE_H
#define ROPE_H

#include "CGL/CGL.h"
#include "mass.h"
#include "spring.h"

using namespace std;

namespace CGL {

// The student's own rope.h: the damping as members, a destructor, and a method of their own.
class Rope {
 public:
  Rope(vector<Mass *> &masses, vector<Spring *> &springs) : masses(masses), springs(springs) {}
  Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, const vector<int> &pinned_nodes);
  ~Rope();

  void simulateVerlet(float delta_t, Vector2D gravity);
  void simulateEuler(float delta_t, Vector2D gravity);

  vector<Mass *> masses;
  vector<Spring *> springs;

 private:
  void gather_forces();

  double k_d = 0.01;
  float damping_factor = 0.00005f;
};

}  // namespace CGL

#endif /* ROPE_H */
