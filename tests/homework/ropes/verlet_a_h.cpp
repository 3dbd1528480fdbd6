// A rope.cpp with one planted mistake (rope_with.hpp: VERLET_A_H).
// expect: fail verlet-a-h
// expect-says: multiplied by delta_t once
#define VERLET_A_H
#include "rope_with.hpp"
