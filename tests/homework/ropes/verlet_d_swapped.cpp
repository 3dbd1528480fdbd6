// A rope.cpp with one planted mistake (rope_with.hpp: VERLET_D_SWAPPED).
// expect: fail verlet-d-swapped
#define VERLET_D_SWAPPED
#include "rope_with.hpp"
