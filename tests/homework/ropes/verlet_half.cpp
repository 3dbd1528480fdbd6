// A rope.cpp with one planted mistake (rope_with.hpp: VERLET_HALF).
// expect: fail verlet-half
#define VERLET_HALF
#include "rope_with.hpp"
