// A correct rope.cpp with no damping (rope_with.hpp: NO_DAMPING).
// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: order 2.0
// expect-says: energy holds
#define NO_DAMPING
#include "rope_with.hpp"
