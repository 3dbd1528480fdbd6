// A rope.cpp with one planted mistake (rope_with.hpp: VELOCITY_NOT_STORED).
// expect: fail velocity-not-stored
// expect-verlet: verlet
#define VELOCITY_NOT_STORED
#include "rope_with.hpp"
