// A correct rope.cpp whose simulateVerlet holds the springs as constraints (rope_with.hpp: CONSTRAINTS).
// expect: pass
// expect-verlet: constraints
// expect-says: a spring stretched by 25 % is back at its rest length after one step
// expect-says: damping: each step keeps 1 - d of a mass's velocity, d = 5e-05
// expect-says: gravity: each free mass falls at g
#define CONSTRAINTS
#include "rope_with.hpp"
