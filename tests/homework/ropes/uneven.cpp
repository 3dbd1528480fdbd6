// A rope.cpp with one planted mistake (rope_with.hpp: UNEVEN).
// expect: fail spacing-n
// expect-says: mass 15 is at (7.031, 0), not at (7.5, 0): the masses are spaced by i / num_nodes
// expect-says: checked on springlab's own rope
// expect-euler: symplectic-euler
// expect-verlet: verlet
#define UNEVEN
#include "rope_with.hpp"
