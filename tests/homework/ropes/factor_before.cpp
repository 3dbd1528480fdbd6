// A correct rope.cpp, Euler damped by a factor a step (rope_with.hpp: FACTOR_BEFORE).
// expect: pass
// expect-euler: symplectic-euler
// expect-says: a global damping factor on the velocity, v = (1 - d) v each step, d = 5e-05
// expect-says: order: not measured: a damping factor d a step has no limit
#define FACTOR_BEFORE
#include "rope_with.hpp"
