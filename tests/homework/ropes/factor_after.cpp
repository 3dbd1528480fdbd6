// A correct rope.cpp, Euler damped by a factor a step (rope_with.hpp: FACTOR_AFTER).
// expect: pass
// expect-euler: symplectic-euler
// expect-says: taken from the new velocity after the position has moved by the undamped one
#define FACTOR_AFTER
#include "rope_with.hpp"
