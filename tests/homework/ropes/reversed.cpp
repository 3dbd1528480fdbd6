// A rope.cpp with one planted mistake (rope_with.hpp: REVERSED).
// expect: fail reversed
// expect-says: the rope is laid from end to start
// expect-euler: symplectic-euler
#define REVERSED
#include "rope_with.hpp"
