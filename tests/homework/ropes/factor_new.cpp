// A correct rope.cpp, Euler damped by a factor a step (rope_with.hpp: FACTOR_NEW).
// expect: pass
// expect-euler: symplectic-euler
// expect-says: taken from the new velocity: v = (1 - d)(v + a h)
#define FACTOR_NEW
#include "rope_with.hpp"
